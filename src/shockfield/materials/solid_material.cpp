#include "shockfield/materials/solid_material.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

void SolidMaterial::validate() const {
  const std::string where = fmt::format("material '{}'", name);
  eos.validate(where);
  strength.validate(where);
  thermal.validate(where);
  viscosity.validate(where);
  spall.validate(where);
}

double SolidMaterial::longitudinal_speed(double rho, double e) const {
  return longitudinal_speed(eos.hugoniot(rho), e);
}

double SolidMaterial::longitudinal_speed(const MieGruneisen::HugoniotPoint& h, double e) const {
  return std::sqrt(eos.sound_speed_squared(h, e) + 4.0 * strength.shear_modulus / (3.0 * h.rho));
}

namespace {

// a += dt·(W·a − a·W) for a symmetric a and an antisymmetric W (the Jaumann terms of eq. 1):
// a·W = −(W·a)ᵀ, so the increment is W·a + (W·a)ᵀ, symmetric by construction.
[[gnu::always_inline]] inline void jaumann_rotate(Mat3& a, const Mat3& w, double dt) {
  Mat3 wa;
  wa.noalias() = w * a;
  a += dt * (wa + wa.transpose());
}

}  // namespace

PointState SolidMaterial::initial_state() const {
  PointState p;
  p.temperature = thermal.initial_temperature;
  p.shock_volume = 1.0 / eos.rho0;
  p.sound_speed = longitudinal_speed(eos.rho0, 0.0);
  return p;
}

void SolidMaterial::update(PointState& p, double rho_ref, const Mat3& velocity_gradient, double dt,
                           double length) const {
  const Mat3& l = velocity_gradient;
  const double j_old = p.deformation.determinant();
  p.deformation = (Mat3::Identity() + dt * l) * p.deformation;
  const double j_new = p.deformation.determinant();
  if (!(j_new > 0.0) || !std::isfinite(j_new))
    throw RunError(fmt::format("material '{}': a point was inverted (det F = {})", name, j_new));
  const double v_ref = 1.0 / rho_ref;
  const double v_old = j_old * v_ref, v_new = j_new * v_ref, dv = v_new - v_old;
  const double rho_new = 1.0 / v_new;

  // Deviatoric part (eqs. 1-4) on the Jaumann-rotated stress: ṡ = Ws − sW + 2G(ė − ė^p).
  Mat3 d, w;  // symmetric and antisymmetric parts of L, element by element
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) {
      d(r, c) = 0.5 * (l(r, c) + l(c, r));
      w(r, c) = 0.5 * (l(r, c) - l(c, r));
    }
  J2Plasticity::State& dev = p.deviatoric;
  jaumann_rotate(dev.s, w, dt);
  if (strength.isotropic_fraction < 1.0) jaumann_rotate(dev.back_stress, w, dt);  // α ≡ 0 otherwise
  const Mat3 s_rotated = dev.s;
  const Mat3 de = deviator(d) * dt;
  const J2Plasticity::Increment plastic = strength.update(dev, de);

  // Artificial viscosity from the compression rate.
  p.viscous_pressure = viscosity.pressure(rho_new, p.sound_speed, d.trace(), length);

  // Energy, de = v·s:ė dt − (P̄ + q)dv with P̄ the trapezoidal mean; P_new = a + b·e_new (eq. 5)
  // is linear in e, so the implicit trapezoidal rule is solved exactly. This makes the discrete
  // jump satisfy the Rankine-Hugoniot energy condition.
  const double w_dev = 0.5 * (v_old + v_new) * 0.5 * (s_rotated + dev.s).cwiseProduct(de).sum();
  const double b = eos.energy_coefficient();
  const MieGruneisen::HugoniotPoint hugoniot = eos.hugoniot(rho_new);
  const double a = hugoniot.ph - b * hugoniot.eh;
  const double e_new = (p.energy + w_dev - 0.5 * (p.pressure + a + 2.0 * p.viscous_pressure) * dv) / (1.0 + 0.5 * b * dv);
  p.energy = e_new;
  p.pressure = a + b * e_new;

  // Temperature (eqs. 7-8) with the plastic work s:Δe^p per unit mass.
  const double dwp = v_new * dev.s.cwiseProduct(plastic.plastic).sum();
  p.plastic_work += dwp;
  p.temperature = thermal.advance(eos, v_old, v_new, p.temperature, dwp, p.shock_volume);
  p.sound_speed = longitudinal_speed(hugoniot, e_new);
  spall.apply(p, dv, 0.5 * (v_old + v_new), de);
  if (!std::isfinite(p.pressure) || !std::isfinite(p.temperature))
    throw RunError(fmt::format("material '{}': non-finite pressure or temperature (ρ = {} kg/m³)", name, rho_new));
}

}  // namespace shockfield::materials
