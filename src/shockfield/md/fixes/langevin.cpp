#include "shockfield/md/fixes/langevin.hpp"

#include <cmath>

#include "shockfield/core/rng.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::mvv2e;

FixLangevin::FixLangevin(double temperature, double damping, std::uint64_t seed, std::uint32_t group_bit)
    : FixNve(group_bit), temperature_(temperature), damping_(damping), seed_(seed) {}

void FixLangevin::post_force(Simulation& sim) {
  Atoms& a = sim.atoms;
  bath_force_.assign(a.nlocal, Vec3::Zero());
  const auto step = static_cast<std::uint64_t>(sim.step);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (!(a.mask[i] & group_bit_)) continue;
    const double m = a.mass_of(i);
    // Friction −m v/τ (amu·Å/ps²) and random force, both converted to eV/Å by mvv2e.
    const double sigma = std::sqrt(2.0 * m * boltz * temperature_ * mvv2e / (damping_ * sim.dt));
    const auto id = static_cast<std::uint64_t>(a.id[i]);
    Vec3 f = -(m * mvv2e / damping_) * a.v[i];
    for (int d = 0; d < 3; ++d) f[d] += sigma * rng::normal(seed_, step, id, static_cast<std::uint64_t>(d));
    bath_force_[i] = f;
    a.f[i] += f;
  }
}

void FixLangevin::final_integrate(Simulation& sim) {
  FixNve::final_integrate(sim);
  // Work done by the bath over the step, with the end-of-step velocities (trapezoid-free
  // estimate, adequate for the conserved-quantity diagnostic).
  double work = 0;
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i) work += bath_force_[i].dot(sim.atoms.v[i]);
  if (sim.atoms.ranks) work = sim.atoms.ranks->sum({work})[0];  // every rank's atoms: the same tally on each
  energy_added_ += work * sim.dt;
}

}  // namespace shockfield::md
