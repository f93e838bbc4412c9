#include "shockfield/pd/constitutive.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {

SmallStrainJ2 SmallStrainJ2::from_young(double density, double young, double poisson, double yield, double hardening,
                                        double slope) {
  if (!(density > 0.0)) throw InputError(fmt::format("pd material: density {} (expected > 0 kg/m³)", density));
  if (!(slope >= 0.0)) throw InputError(fmt::format("pd material: Hugoniot slope {} (expected >= 0)", slope));
  SmallStrainJ2 m;
  m.density = density;
  m.deviatoric = materials::J2Plasticity::from_young(young, poisson, yield, hardening);
  m.deviatoric.validate("pd material");
  m.bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  m.slope = slope;
  return m;
}

Mat3 SmallStrainJ2::update(State& s, const Mat3& /*f_old*/, const Mat3& f_new, double /*dt*/) const {
  const Mat3 strain = 0.5 * (f_new + f_new.transpose()) - Mat3::Identity();
  deviatoric.update(s.dev, materials::deviator(strain - s.strain));
  s.strain = strain;
  return s.dev.s + bulk * strain.trace() * Mat3::Identity();
}

std::size_t StateLayout::grain_size() const {
  std::size_t n = 0;
  for (const StateField& f : fields) n += f.count;
  return n;
}

StateLayout SmallStrainJ2::state_layout() const {
  return {{{"strain", "1", 9}, {"deviatoric_stress", "Pa", 9}, {"back_stress", "Pa", 9}, {"plastic_strain", "1", 1}}};
}

void SmallStrainJ2::save(const State& s, double* out) const {
  std::copy_n(s.strain.data(), 9, out);
  std::copy_n(s.dev.s.data(), 9, out + 9);
  std::copy_n(s.dev.back_stress.data(), 9, out + 18);
  out[27] = s.dev.plastic_strain;
}

void SmallStrainJ2::load(State& s, const double* in) const {
  s.strain = Mat3(in);
  s.dev.s = Mat3(in + 9);
  s.dev.back_stress = Mat3(in + 18);
  s.dev.plastic_strain = in[27];
}

}  // namespace shockfield::pd
