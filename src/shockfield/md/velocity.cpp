#include "shockfield/md/velocity.hpp"

#include <cmath>

#include "shockfield/core/rng.hpp"
#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::mvv2e;

double group_twice_kinetic(const Atoms& atoms, std::uint32_t group_bit, std::size_t& count) {
  double sum = 0;
  count = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    if (!(atoms.mask[i] & group_bit)) continue;
    sum += atoms.mass_of(i) * atoms.v[i].squaredNorm();
    ++count;
  }
  if (atoms.ranks) {  // a decomposed run: every rank's atoms, partial sums added in rank order
    const std::vector<double> total = atoms.ranks->sum({sum, static_cast<double>(count)});
    sum = total[0];
    count = static_cast<std::size_t>(total[1]);
  }
  return sum * mvv2e;
}

Vec3 group_twice_kinetic_components(const Atoms& atoms, std::uint32_t group_bit) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if (atoms.mask[i] & group_bit) sum += atoms.mass_of(i) * atoms.v[i].cwiseProduct(atoms.v[i]);
  return sum * mvv2e;
}

double group_temperature(const Atoms& atoms, std::uint32_t group_bit) {
  std::size_t n = 0;
  const double twice_ke = group_twice_kinetic(atoms, group_bit, n);
  if (n < 2) return 0.0;
  return twice_ke / ((3.0 * static_cast<double>(n) - 3.0) * boltz);
}

void create_velocities(Atoms& atoms, double temperature, std::uint64_t seed, std::uint32_t group_bit) {
  Vec3 momentum = Vec3::Zero();
  double mass = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    if (!(atoms.mask[i] & group_bit)) continue;
    const double m = atoms.mass_of(i);
    const double sigma = std::sqrt(boltz * temperature / (m * mvv2e));
    const auto id = static_cast<std::uint64_t>(atoms.id[i]);
    for (int d = 0; d < 3; ++d) atoms.v[i][d] = sigma * rng::normal(seed, id, static_cast<std::uint64_t>(d));
    momentum += m * atoms.v[i];
    mass += m;
  }
  if (mass == 0) return;
  const Vec3 drift = momentum / mass;
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if (atoms.mask[i] & group_bit) atoms.v[i] -= drift;
  const double current = group_temperature(atoms, group_bit);
  if (current <= 0) return;
  const double scale = std::sqrt(temperature / current);
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if (atoms.mask[i] & group_bit) atoms.v[i] *= scale;
}

void add_velocity(Atoms& atoms, const Vec3& velocity, std::uint32_t group_bit) {
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if (atoms.mask[i] & group_bit) atoms.v[i] += velocity;
}

}  // namespace shockfield::md
