#include "shockfield/pd/crystal_material.hpp"

#include <algorithm>

namespace shockfield::pd {

double CrystalMaterial::longitudinal_modulus() const {
  const Vec3 a = orientation.transpose() * Vec3::UnitX();
  const double quartic = a.array().pow(4).sum();
  return crystal.c12 + 2.0 * crystal.c44 + (crystal.c11 - crystal.c12 - 2.0 * crystal.c44) * quartic;
}

void CrystalMaterial::save(const State& s, double* out) const {
  const std::size_t n = crystal.systems.size();
  std::copy_n(s.orientation.data(), 9, out);
  std::copy_n(s.lattice.data(), 9, out + 9);
  std::copy_n(s.fp.data(), 9, out + 18);
  std::copy_n(s.resistance.data(), n, out + 27);
  std::copy_n(s.slip.data(), n, out + 27 + n);
  out[27 + 2 * n] = s.accumulated_slip;
  out[28 + 2 * n] = static_cast<double>(s.substeps);
}

void CrystalMaterial::load(State& s, const double* in) const {
  const std::size_t n = crystal.systems.size();
  s.orientation = Mat3(in);
  s.lattice = Mat3(in + 9);
  s.fp = Mat3(in + 18);
  s.resistance.assign(in + 27, in + 27 + n);
  s.slip.assign(in + 27 + n, in + 27 + 2 * n);
  s.accumulated_slip = in[27 + 2 * n];
  s.substeps = static_cast<long long>(in[28 + 2 * n]);
}

}  // namespace shockfield::pd
