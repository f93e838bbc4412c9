#include "shockfield/materials/spall.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/solid_material.hpp"

namespace shockfield::materials {

void SpallFailure::validate(const std::string& where) const {
  if (!(strength >= 0.0) || !std::isfinite(strength))
    throw InputError(fmt::format(
        "{}: spall_strength = {} (expected >= 0 Pa; 0 = no tensile failure)", where, strength));
  if (!(tuler_butcher_exponent >= 0.0) || !std::isfinite(tuler_butcher_exponent))
    throw InputError(fmt::format("{}: spall_tuler_butcher_exponent = {} (expected >= 0; 0 = instantaneous failure)",
                                 where, tuler_butcher_exponent));
  if (tuler_butcher_exponent > 0.0 && !(tuler_butcher_integral > 0.0 && std::isfinite(tuler_butcher_integral)))
    throw InputError(fmt::format("{}: spall_tuler_butcher_integral = {} (expected > 0 Pa^lambda s with "
                                 "spall_tuler_butcher_exponent = {})", where, tuler_butcher_integral,
                                 tuler_butcher_exponent));
  if (tuler_butcher_exponent > 0.0 && !(strength > 0.0))
    throw InputError(fmt::format("{}: spall_tuler_butcher_exponent = {} needs spall_strength > 0 (the threshold "
                                 "sigma_0 of the damage integral)", where, tuler_butcher_exponent));
}

void SpallFailure::apply(PointState& p, double dv, double v_mean, const Mat3& de, double dt) const {
  if (!enabled()) return;
  const double over = -(p.pressure + p.viscous_pressure) - strength;  // σ_t − σ_0
  if (p.damage < 1.0 && over > 0.0) {
    if (tuler_butcher_exponent > 0.0)  // D += (σ_t − σ_0)^λ Δt / K_f (Tuler & Butcher 1968)
      p.damage = std::min(1.0, p.damage + std::pow(over, tuler_butcher_exponent) * dt / tuler_butcher_integral);
    else
      p.damage = 1.0;
  }
  if (p.damage < 1.0) return;
  p.energy -= v_mean * 0.5 * p.deviatoric.s.cwiseProduct(de).sum();
  p.deviatoric.s.setZero();
  if (p.pressure < 0.0) {
    p.energy += 0.5 * p.pressure * dv;
    p.pressure = 0.0;
  }
}

}  // namespace shockfield::materials
