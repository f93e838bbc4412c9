#pragma once
// How the MD engine (LAMMPS metal units: Å, eV, amu, ps, K) runs the macroparticle model: the
// engine's Å is the particle spacing r0, its eV the bond energy D and its amu the particle mass
// M, so the pair law has r0 = D = M = 1 inside the engine and every engine constant (ftm2v,
// mvv2e, boltz) keeps its meaning. The engine's ps is then the time τ with M r0²/τ² = D·mvv2e,
// and its K is the temperature T with boltz·T·D = k_B T_SI. The case file and every output are
// SI; these conversions are the only place the two meet (docs/theory/macroparticle.md).
#include <cmath>

#include "shockfield/core/units.hpp"

namespace shockfield::macroparticle {

struct ReducedUnits {
  double length = 1;  ///< m per engine Å (r0)
  double energy = 1;  ///< J per engine eV (D)
  double mass = 1;    ///< kg per engine amu (M)

  /// s per engine ps.
  double time() const { return length * std::sqrt(mass / (energy * units::metal::mvv2e)); }
  double velocity() const { return length / time(); }      ///< m/s per engine Å/ps
  double force() const { return energy / length; }         ///< N per engine eV/Å
  double stress() const { return energy / (length * length * length); }  ///< Pa per engine eV/Å³
  /// K (SI) per engine K.
  double temperature() const { return units::metal::boltz * energy / units::si::boltz; }
};

}  // namespace shockfield::macroparticle
