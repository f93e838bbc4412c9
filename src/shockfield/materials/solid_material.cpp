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

PointState SolidMaterial::initial_state() const {
  PointState p;
  p.temperature = thermal.initial_temperature;
  p.shock_volume = 1.0 / eos.rho0;
  p.sound_speed = longitudinal_speed(eos.rho0, 0.0);
  return p;
}

void SolidMaterial::update(PointState& p, double rho_ref, const Mat3& velocity_gradient, double dt, double length,
                           bool plane_strain) const {
  if (plane_strain) update_coupled<2>(p, rho_ref, velocity_gradient, dt, length);
  else update_coupled<3>(p, rho_ref, velocity_gradient, dt, length);
}

template <int N>
void SolidMaterial::update_coupled(PointState& p, double rho_ref, const Mat3& velocity_gradient, double dt,
                                   double length) const {
  // The 3×3 algebra is written out on scalars: Eigen's temporaries here were stored element by
  // element and read back as 16-byte packets, which defeats store-to-load forwarding. Sums run
  // in a fixed order (a0 + (a1 + a2) for the products), which reproduces the former Eigen code
  // bit for bit in plane strain and to round-off in 3D. With N = 2 (plane strain in
  // x, y: L_iz = L_zi = 0) only the in-plane coefficients and the zz one of the deviators are
  // formed; the others are zero and stay so (F_zz = 1), up to the sign of a zero.
  constexpr auto coupled = [](int r, int c) { return N == 3 || (r < N && c < N); };
  constexpr auto deviatoric = [](int r, int c) { return N == 3 || (r < N && c < N) || (r == 2 && c == 2); };
  const Mat3& l = velocity_gradient;
  Mat3& f = p.deformation;
  const double j_old = f.determinant();
  {  // F ← (I + Δt·L)·F
    double fn[3][3];
    for (int r = 0; r < 3; ++r) {
      const double a0 = (r == 0 ? 1.0 : 0.0) + dt * l(r, 0), a1 = (r == 1 ? 1.0 : 0.0) + dt * l(r, 1),
                   a2 = (r == 2 ? 1.0 : 0.0) + dt * l(r, 2);
      for (int c = 0; c < 3; ++c)
        if (coupled(r, c)) fn[r][c] = a0 * f(0, c) + (a1 * f(1, c) + a2 * f(2, c));
    }
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        if (coupled(r, c)) f(r, c) = fn[r][c];
  }
  const double j_new = f.determinant();
  if (!(j_new > 0.0) || !std::isfinite(j_new))
    throw RunError(fmt::format("material '{}': a point was inverted (det F = {})", name, j_new));
  const double v_ref = 1.0 / rho_ref;
  const double v_old = j_old * v_ref, v_new = j_new * v_ref, dv = v_new - v_old;
  const double rho_new = 1.0 / v_new;

  // Deviatoric part (eqs. 1-4) on the Jaumann-rotated stress: ṡ = Ws − sW + 2G(ė − ė^p), with
  // D and W the symmetric and antisymmetric parts of L.
  // (Formed from L where used: stored as arrays they became packed temporaries again.)
  auto d = [&](int r, int c) { return 0.5 * (l(r, c) + l(c, r)); };
  auto w = [&](int r, int c) { return 0.5 * (l(r, c) - l(c, r)); };
  // a += Δt·(W·a − a·W) for a symmetric a: a·W = −(W·a)ᵀ, so the increment W·a + (W·a)ᵀ is
  // symmetric by construction (formed once per pair of coefficients, no 3×3 temporary). In
  // plane strain W has no z couplings, so a_zz does not change.
  // `rotated` (if given) receives the rotated coefficients as they are formed.
  auto jaumann_rotate = [&](Mat3& a, double* rotated) {
    auto wa = [&](int r, int c) { return w(r, 0) * a(0, c) + (w(r, 1) * a(1, c) + w(r, 2) * a(2, c)); };
    double inc[6];
    for (int r = 0, k = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c, ++k)
        if (coupled(r, c)) inc[k] = dt * (wa(r, c) + wa(c, r));
    for (int r = 0, k = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c, ++k)
        if (coupled(r, c)) {
          a(r, c) += inc[k];
          if (c != r) a(c, r) += inc[k];
          if (rotated) rotated[r + 3 * c] = a(r, c), rotated[c + 3 * r] = a(c, r);
        }
    if (N == 2 && rotated) rotated[8] = a(2, 2);
  };
  // The deviatoric state is updated in place and never copied as a whole: a coefficient stored
  // and read back at once as part of a 16-byte packet (Eigen or memcpy copies) stalls store
  // forwarding. (This file is compiled without auto-vectorisation for the same reason.)
  J2Plasticity::State& dev = p.deviatoric;
  const bool kinematic = strength.isotropic_fraction < 1.0;  // α ≡ 0 otherwise
  double s_rotated[9];
  jaumann_rotate(dev.s, s_rotated);
  if (kinematic) jaumann_rotate(dev.back_stress, nullptr);
  const double trace_d = d(0, 0) + (d(1, 1) + d(2, 2));
  Mat3 de;  // deviator of D·Δt
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      de(r, c) = deviatoric(r, c) ? (d(r, c) - (trace_d / 3.0) * (r == c ? 1.0 : 0.0)) * dt : 0.0;
  const J2Plasticity::Increment plastic = strength.update<N>(dev, de);
  Mat3 s_sum;  // s before and after the return, for the trapezoidal work below
  for (int k = 0; k < 9; ++k)
    if (J2Plasticity::plane_coefficient<N>(k)) s_sum.data()[k] = s_rotated[k] + dev.s.data()[k];

  // Artificial viscosity from the compression rate.
  p.viscous_pressure = viscosity.pressure(rho_new, p.sound_speed, trace_d, length);

  // Energy, de = v·s:ė dt − (P̄ + q)dv with P̄ the trapezoidal mean; P_new = a + b·e_new (eq. 5)
  // is linear in e, so the implicit trapezoidal rule is solved exactly. This makes the discrete
  // jump satisfy the Rankine-Hugoniot energy condition.
  const double w_dev = 0.5 * (v_old + v_new) * 0.5 * J2Plasticity::contract<N>(s_sum, de);
  const double b = eos.energy_coefficient();
  const MieGruneisen::HugoniotPoint hugoniot = eos.hugoniot(rho_new);
  const double a = hugoniot.ph - b * hugoniot.eh;
  const double e_new = (p.energy + w_dev - 0.5 * (p.pressure + a + 2.0 * p.viscous_pressure) * dv) / (1.0 + 0.5 * b * dv);
  p.energy = e_new;
  p.pressure = a + b * e_new;

  // Temperature (eqs. 7-8) with the plastic work s:Δe^p per unit mass.
  const double dwp = plastic.equivalent > 0.0 ? v_new * J2Plasticity::contract<N>(dev.s, plastic.plastic) : 0.0;
  p.plastic_work += dwp;
  p.temperature = thermal.advance(eos, v_old, v_new, p.temperature, dwp, p.shock_volume);
  p.sound_speed = longitudinal_speed(hugoniot, e_new);
  if (spall.enabled()) spall.apply(p, dv, 0.5 * (v_old + v_new), de, dt);
  if (!std::isfinite(p.pressure) || !std::isfinite(p.temperature))
    throw RunError(fmt::format("material '{}': non-finite pressure or temperature (ρ = {} kg/m³)", name, rho_new));
}

}  // namespace shockfield::materials
