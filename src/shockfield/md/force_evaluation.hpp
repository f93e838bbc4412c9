#pragma once
// One complete force evaluation on the current ghosts and neighbour list: zero the forces,
// let the potential add its pair and many-body terms, fold ghost forces and per-atom tallies
// back onto their owners (LAMMPS "reverse communication").
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md {

void evaluate_forces(Atoms& atoms, Potential& potential, const geometry::NeighborList& list,
                     ForceResult& result, bool per_atom);

}  // namespace shockfield::md
