#include "shockfield/materials/strength/j2_plasticity.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

double von_mises(const Mat3& s) { return std::sqrt(1.5) * s.norm(); }

J2Plasticity J2Plasticity::from_young(double young, double poisson, double yield0, double tangent,
                                      double isotropic_fraction) {
  if (!(young > 0.0)) throw InputError(fmt::format("J2 plasticity: Young's modulus E = {} (expected > 0 Pa)", young));
  if (!(poisson > -1.0 && poisson < 0.5))
    throw InputError(fmt::format("J2 plasticity: Poisson's ratio ν = {} (expected -1 < ν < 0.5)", poisson));
  return {young / (2.0 * (1.0 + poisson)), yield0, tangent, isotropic_fraction};
}

void J2Plasticity::validate(const std::string& where) const {
  auto require = [&](bool ok, const char* name, const char* expected, double value) {
    if (!ok) throw InputError(fmt::format("{}: J2 plasticity {} = {} (expected {})", where, name, value, expected));
  };
  require(shear_modulus > 0.0 && std::isfinite(shear_modulus), "shear_modulus", "> 0 Pa", shear_modulus);
  require(yield_stress0 > 0.0, "yield_stress0", "> 0 Pa", yield_stress0);
  require(tangent_modulus >= 0.0 && std::isfinite(tangent_modulus), "tangent_modulus", ">= 0 Pa", tangent_modulus);
  require(isotropic_fraction >= 0.0 && isotropic_fraction <= 1.0, "isotropic_fraction", "a value in [0, 1]",
          isotropic_fraction);
}

}  // namespace shockfield::materials
