#pragma once
// Zero-temperature cubic elastic constants of a crystal and potential, by the strain–stress
// procedure of the LAMMPS ELASTIC example (examples/ELASTIC in the LAMMPS distribution):
//  1. the crystal is relaxed to zero pressure (FIRE with box relaxation) → a0 and the cohesive
//     energy E/N;
//  2. the crystal, rebuilt at a0, is stretched along x by ±ε (atoms follow affinely, then are
//     relaxed at fixed box, which gives any internal relaxation); with σ = −P (virial pressure
//     tensor) and central differences, C11 = ∂σxx/∂ε and C12 = ½ ∂(σyy + σzz)/∂ε;
//  3. the crystal rotated to x = [110], y = [−110], z = [001] is stretched the same way: there
//     C'11 = (C11 + C12)/2 + C44 and C'12 = (C11 + C12)/2 − C44 (cubic tensor rotated by 45°
//     about z; Nye, Physical Properties of Crystals, 1957, ch. VIII), so
//     C44 = ½ ∂(σxx − σyy)/∂ε. This keeps the box orthogonal (shockfield has no tilted boxes).
// The LAMMPS input doing the same is tests/fixtures/lammps_elastic/in.elastic.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/md/lattice.hpp"
#include "shockfield/md/minimize.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md {

/// A cubic crystal: `lattice.style` sc, bcc, fcc or diamond (orient is ignored), `lattice.a0`
/// the starting guess for the relaxation; masses (amu) and element names per atom type.
struct CubicCrystal {
  LatticeSpec lattice;
  std::vector<double> mass;
  std::vector<std::string> type_names;
};

struct ElasticSettings {
  std::array<int, 3> repeat{4, 4, 4};  ///< periodic repeats of the (cubic and rotated) cells
  double strain = 1e-3;                ///< ε of the central differences
  double force_tolerance = 1e-10;      ///< eV/Å, FIRE stop
  double pressure_tolerance = 1e-5;    ///< bar, box relaxation stop
  long long max_iterations = 200000;
  double fire_timestep = 0.002;        ///< ps, FIRE's starting step
};

struct CubicElasticConstants {
  double a0 = 0;               ///< Å, zero-pressure lattice constant
  double cohesive_energy = 0;  ///< eV/atom (E/N of the relaxed crystal, negative when bound)
  double c11 = 0, c12 = 0, c44 = 0;  ///< GPa
  MinimizeResult relaxation;   ///< the zero-pressure relaxation of step 1
  double bulk_modulus() const { return (c11 + 2.0 * c12) / 3.0; }
};

/// Makes a fresh potential for each crystal the procedure builds.
using PotentialFactory = std::function<std::unique_ptr<Potential>()>;

/// Runs steps 1–3 above; throws RunError when a relaxation does not converge and InputError when
/// the lattice is not cubic.
CubicElasticConstants cubic_elastic_constants(const CubicCrystal& crystal, const PotentialFactory& potential,
                                              const ElasticSettings& settings = {});

}  // namespace shockfield::md
