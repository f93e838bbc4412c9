#pragma once
// Periodic images as ghost atoms (LAMMPS "comm" semantics on one process): for each periodic
// dimension in turn (x, then y, then z, ghosts of earlier dimensions included), every atom within
// `cutoff` of a face is copied to the opposite side. Boxes thinner than the cutoff get several
// layers of images. The ghosts are counted and written by all threads in the order a serial loop
// would write them, so the ghost list does not depend on the thread count.
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

/// Wraps owned atoms into the periodic box and recreates all ghosts within `cutoff` of a face
/// (positions, types, owners and images; the force array is sized to match).
void rebuild_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff);

/// rebuild_ghosts() without the force array, for callers that only search neighbours (the
/// structure analysis of atoms): `atoms` holds owned entries only (x, type, image).
void append_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff);

/// A capacity for owned + ghost entries when atoms fill the box uniformly: n Π(1 + 2 cutoff/L)
/// over periodic dimensions, with 5 % to spare. Reserving it lets the ghosts be appended in place
/// (no reallocation copying the owned atoms on one thread).
std::size_t ghost_capacity(std::size_t nlocal, const geometry::Box& box, double cutoff);

/// The most owned + ghost entries the box can give, however the atoms lie: an entry has at most
/// 2 k + 1 images along a periodic dimension with k = ceil(cutoff / L) image layers, so
/// n Π(2 k + 1). Reserved, it keeps x, type and f in place through every rebuild in this box.
std::size_t most_entries(std::size_t nlocal, const geometry::Box& box, double cutoff);

}  // namespace shockfield::md
