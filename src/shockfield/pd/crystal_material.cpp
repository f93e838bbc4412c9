#include "shockfield/pd/crystal_material.hpp"

#include <algorithm>

namespace shockfield::pd {

double CrystalMaterial::longitudinal_modulus() const {
  const auto& c = aggregate.crystal;
  double sum = 0.0;
  for (const Mat3& g : aggregate.orientations) {
    const Vec3 a = g.transpose() * Vec3::UnitX();
    sum += c.c12 + 2.0 * c.c44 + (c.c11 - c.c12 - 2.0 * c.c44) * a.array().pow(4).sum();
  }
  return sum / static_cast<double>(aggregate.orientations.size());
}

StateLayout CrystalMaterial::state_layout() const {
  const std::size_t n = aggregate.crystal.systems.size();
  return {{{"orientation", "1", 9},
           {"lattice", "1", 9},
           {"plastic_deformation_gradient", "1", 9},
           {"slip_resistance", "Pa", n},
           {"slip", "1", n},
           {"accumulated_slip", "1", 1},
           {"substeps", "1", 1, true}},
          true,
          aggregate.orientations.size()};
}

void CrystalMaterial::save(const State& state, double* out) const {
  const std::size_t n = aggregate.crystal.systems.size(), grain_size = state_layout().grain_size();
  for (const auto& s : state) {
    std::copy_n(s.orientation.data(), 9, out);
    std::copy_n(s.lattice.data(), 9, out + 9);
    std::copy_n(s.fp.data(), 9, out + 18);
    std::copy_n(s.resistance.data(), n, out + 27);
    std::copy_n(s.slip.data(), n, out + 27 + n);
    out[27 + 2 * n] = s.accumulated_slip;
    out[28 + 2 * n] = static_cast<double>(s.substeps);
    out += grain_size;
  }
}

void CrystalMaterial::load(State& state, const double* in) const {
  const std::size_t n = aggregate.crystal.systems.size(), grain_size = state_layout().grain_size();
  state.resize(aggregate.orientations.size());
  for (auto& s : state) {
    s.orientation = Mat3(in);
    s.lattice = Mat3(in + 9);
    s.fp = Mat3(in + 18);
    s.resistance.assign(in + 27, in + 27 + n);
    s.slip.assign(in + 27 + n, in + 27 + 2 * n);
    s.accumulated_slip = in[27 + 2 * n];
    s.substeps = static_cast<long long>(in[28 + 2 * n]);
    in += grain_size;
  }
}

}  // namespace shockfield::pd
