#pragma once
// Periodic images as ghost atoms (LAMMPS "comm" semantics on one process): for each periodic
// dimension in turn (x, then y, then z, ghosts of earlier dimensions included), every atom within
// `cutoff` of a face is copied to the opposite side. Boxes thinner than the cutoff get several
// layers of images.
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

/// Wraps owned atoms into the periodic box and recreates all ghosts within `cutoff` of a face.
void rebuild_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff);

}  // namespace shockfield::md
