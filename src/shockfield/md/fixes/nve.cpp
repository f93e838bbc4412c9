#include "shockfield/md/fixes/nve.hpp"

#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

void FixNve::half_kick(Simulation& sim, bool drift) const {
  Atoms& a = sim.atoms;
  const double dtf = 0.5 * sim.dt * units::metal::ftm2v;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (!(a.mask[i] & group_bit_)) continue;
    a.v[i] += (dtf / a.mass_of(i)) * a.f[i];
    if (drift) a.x[i] += sim.dt * a.v[i];
  }
}

void FixNve::initial_integrate(Simulation& sim) { half_kick(sim, true); }

void FixNve::final_integrate(Simulation& sim) { half_kick(sim, false); }

}  // namespace shockfield::md
