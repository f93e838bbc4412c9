#include "shockfield/materials/spall.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/solid_material.hpp"

namespace shockfield::materials {

void SpallFailure::validate(const std::string& where) const {
  if (!(strength >= 0.0) || !std::isfinite(strength))
    throw InputError(fmt::format(
        "{}: spall_strength = {} (expected >= 0 Pa; 0 = no tensile failure)", where, strength));
}

void SpallFailure::apply(PointState& p, double dv, double v_mean, const Mat3& de) const {
  if (!enabled()) return;
  if (p.damage < 1.0 && p.pressure + p.viscous_pressure < -strength) p.damage = 1.0;
  if (p.damage < 1.0) return;
  p.energy -= v_mean * 0.5 * p.deviatoric.s.cwiseProduct(de).sum();
  p.deviatoric.s.setZero();
  if (p.pressure < 0.0) {
    p.energy += 0.5 * p.pressure * dv;
    p.pressure = 0.0;
  }
}

}  // namespace shockfield::materials
