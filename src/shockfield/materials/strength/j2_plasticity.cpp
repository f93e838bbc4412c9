#include "shockfield/materials/strength/j2_plasticity.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

Mat3 deviator(const Mat3& a) { return a - (a.trace() / 3.0) * Mat3::Identity(); }

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

double J2Plasticity::yield_stress(double plastic_strain) const {
  return yield_stress0 + isotropic_fraction * tangent_modulus * plastic_strain;  // eq. 4
}

J2Plasticity::Increment J2Plasticity::update(State& state, const Mat3& de) const {
  const double g = shear_modulus;
  state.s += 2.0 * g * de;  // elastic trial, s = 2G·e^e
  const Mat3 xi = state.s - state.back_stress;
  const double xi_norm = xi.norm();
  const double f = std::sqrt(1.5) * xi_norm - yield_stress(state.plastic_strain);  // eq. 3
  Increment inc;
  if (f <= 0.0) return inc;
  inc.equivalent = f / (3.0 * g + tangent_modulus);
  inc.plastic = (std::sqrt(1.5) * inc.equivalent / xi_norm) * xi;
  state.s -= 2.0 * g * inc.plastic;
  state.back_stress += (2.0 / 3.0) * (1.0 - isotropic_fraction) * tangent_modulus * inc.plastic;
  state.plastic_strain += inc.equivalent;
  return inc;
}

}  // namespace shockfield::materials
