#include "shockfield/macroparticle/loaded_layers.hpp"

#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::macroparticle {

void FixLoadedLayers::initial_integrate(md::Simulation& sim) {
  md::Atoms& a = sim.atoms;
  const double dtf = 0.5 * sim.dt * units::metal::ftm2v;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    const bool bottom = a.mask[i] & bottom_, top = a.mask[i] & top_;
    if (!bottom && !top) continue;
    if (clamped_) {
      a.v[i].x() = a.v[i].y() = 0.0;
    } else {
      a.v[i].x() += dtf / a.mass_of(i) * a.f[i].x();
      a.v[i].y() += dtf / a.mass_of(i) * a.f[i].y();
    }
    a.v[i].z() = top ? speed_ : -speed_;
    a.x[i] += sim.dt * a.v[i];
  }
}

void FixLoadedLayers::final_integrate(md::Simulation& sim) {
  if (clamped_) return;
  md::Atoms& a = sim.atoms;
  const double dtf = 0.5 * sim.dt * units::metal::ftm2v;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (!(a.mask[i] & (bottom_ | top_))) continue;
    a.v[i].x() += dtf / a.mass_of(i) * a.f[i].x();
    a.v[i].y() += dtf / a.mass_of(i) * a.f[i].y();
  }
}

}  // namespace shockfield::macroparticle
