#include "shockfield/macroparticle/pair_dissipation.hpp"

#include <cmath>

#include "shockfield/core/rng.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/macroparticle/plastic_bonds.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::macroparticle {

void FixPairDissipation::post_force(md::Simulation& sim) {
  md::Atoms& a = sim.atoms;
  const geometry::NeighborList& list = sim.list;
  const auto nlocal = a.nlocal;
  auto owner = [&](std::size_t j) { return j < nlocal ? j : static_cast<std::size_t>(a.ghost_owner[j - nlocal]); };
  // μ v in amu·Å/ps per ps → eV/Å through mvv2e; σ² = 2μ k_B T/Δt in the same units.
  const double mu = viscosity_ * units::metal::mvv2e;
  const double sigma = std::sqrt(2.0 * viscosity_ * units::metal::boltz * temperature_ * units::metal::mvv2e / sim.dt);
  const double cutsq = cutoff_ * cutoff_;
  const auto step = static_cast<std::uint64_t>(sim.step);
  added_.assign(3 * nlocal, 0.0);
  for (std::size_t i = 0; i < nlocal; ++i) {
    for (auto k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list.neighbors[k]);
      if ((a.x[i] - a.x[j]).squaredNorm() >= cutsq) continue;
      const std::size_t oj = owner(j);
      const std::uint64_t bond = BondTable::key(a.id[i], a.id[oj]);
      for (int d = 0; d < 3; ++d) {
        const double f = mu * (a.v[oj][d] - a.v[i][d]) +
                         sigma * rng::normal(seed_, step, bond, static_cast<std::uint64_t>(d));
        a.f[i][d] += f;
        a.f[oj][d] -= f;
        added_[3 * i + static_cast<std::size_t>(d)] += f;
        added_[3 * oj + static_cast<std::size_t>(d)] -= f;
      }
    }
  }
}

void FixPairDissipation::end_of_step(md::Simulation& sim) {
  // Work of the added forces over the step with the end-of-step velocities (the estimate md's
  // fix langevin keeps for the conserved-quantity diagnostic).
  double work = 0;
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i)
    for (int d = 0; d < 3; ++d) work += added_[3 * i + static_cast<std::size_t>(d)] * sim.atoms.v[i][d];
  energy_added_ += work * sim.dt;
}

}  // namespace shockfield::macroparticle
