#pragma once
// The owned atoms of an MD engine as Method::state_arrays (docs/python.md): shared by `method =
// "md"` (metal units) and the macroparticle rod (its engine's reduced units).
#include <string>
#include <vector>

#include "shockfield/core/derived_arrays.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

/// The units of the engine's lengths, velocities, forces and energies, as the arrays' unit text.
struct AtomUnits {
  std::string length, velocity, force, energy;
};

/// positions, velocities, forces (n, 3), types, ids, images and, while computed, energies of the
/// owned atoms. Reserves room for the most ghost entries the box can give first, so that a
/// neighbour rebuild does not move positions, forces, types or energies.
std::vector<StateArray> atom_state_arrays(Simulation& sim, const AtomUnits& units);

/// The box as DerivedArrays (copies; Python's Simulation.box): box_lo, box_hi (LAMMPS's
/// boxlo/boxhi), box_tilt (xy, xz, yz) (3,) and cell (3, 3), the edge vectors a, b, c as rows.
std::vector<DerivedArray> box_arrays(const geometry::Box& box, const std::string& length_unit);

}  // namespace shockfield::md
