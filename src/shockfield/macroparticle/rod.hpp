#pragma once
// The specimen of a macroparticle run on the MD engine (docs/theory/macroparticle.md §3–6): an
// fcc packing of spacing r0 (cubic cell a = √2 r0, axis [001] along z) cut to a cylinder of
// n_phi cells across the diameter and n_h cells along the axis, or to a box of cells; the
// bottom and top layers loaded at a constant strain rate (FixLoadedLayers), the others
// integrated by md's fix nve or fix langevin; and the measures of the loaded rod: strain of the
// loaded layers, virial stress of the whole rod, lateral strain of its middle half.
#include <cstdint>
#include <memory>

#include "shockfield/macroparticle/case_file.hpp"
#include "shockfield/macroparticle/reduced_units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::macroparticle {

/// Group bits of md::Atoms::mask (bit 0 is md's "all").
inline constexpr std::uint32_t kFreeBit = 1u << 1, kBottomBit = 1u << 2, kTopBit = 1u << 3, kMiddleBit = 1u << 4;

/// The rod's state in SI.
struct RodMeasures {
  double time = 0;            ///< s
  double strain = 0;          ///< (z̄_top − z̄_bottom)/L₀ − 1
  double stress = 0;          ///< σ_zz = −W_zz/V₀, Pa (tension positive)
  double lateral_strain = 0;  ///< R_rms/R_rms,0 − 1 of the middle half
  double kinetic = 0, potential = 0;  ///< J
  double temperature = 0;     ///< K, from the kinetic energy (3N − 3 degrees of freedom)
  /// Secant estimates σ/ε and −ε_lat/ε (0 before any strain).
  double youngs() const { return strain != 0 ? stress / strain : 0.0; }
  double poisson() const { return strain != 0 ? -lateral_strain / strain : 0.0; }
};

class Rod {
 public:
  explicit Rod(const MacroparticleCase& c);

  md::Simulation& sim() { return sim_; }
  const md::Simulation& sim() const { return sim_; }
  const ReducedUnits& units() const { return units_; }
  std::size_t size() const { return sim_.atoms.nlocal; }
  /// One step; `per_atom`: the step's forces also fill the per-particle virials (for outputs).
  void advance(bool per_atom);
  RodMeasures measure() const;
  /// σ_zz of each particle, Pa: −(its half of the pair virials)/(r0³/√2); needs per-atom tallies.
  std::vector<double> particle_stress() const;
  /// The bond states of the plastic law (null without [plasticity]).
  const BondTable* bonds() const { return bonds_.get(); }

 private:
  ReducedUnits units_;
  std::shared_ptr<BondTable> bonds_;
  md::Simulation sim_;
  double length0_ = 0;     ///< L₀ between the loaded layers, engine units
  double volume0_ = 0;     ///< N r0³/√2, engine units
  double radius0_sq_ = 0;  ///< mean squared distance from the axis of the middle half at the start
};

}  // namespace shockfield::macroparticle
