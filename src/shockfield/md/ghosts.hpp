#pragma once
// Periodic images as ghost atoms (LAMMPS "comm" semantics on one process): for each periodic
// dimension in turn (x, then y, then z, ghosts of earlier dimensions included), every atom within
// `cutoff` of a face is copied to the opposite side. Boxes thinner than the cutoff get several
// layers of images. This is the one-rank case of the particle exchange of a decomposed run
// (parallel/particle_exchange.hpp, md/decomposition.hpp): the same swaps, each one a copy to
// itself. The ghosts are selected and written by all threads in the order a serial loop would
// write them, so the ghost list does not depend on the thread count.
#include <array>

#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/parallel/particle_exchange.hpp"

namespace shockfield::md {

/// Atoms as the particle exchange sees them for ghosts: the coordinate is the position (the
/// fractional one in a triclinic cell); a ghost record is the imaged position, the type, the
/// owning atom (owners collapsed: a ghost of a ghost names the owned atom; -1 when it is on
/// another rank) and the image counts relative to it.
struct GhostAtoms {
  Atoms& atoms;
  const geometry::Box& box;
  bool triclinic;
  static constexpr int ghost_width = 8;
  std::size_t size() const { return atoms.size(); }
  double coordinate(std::size_t i, int d) const;
  void pack_ghost(std::size_t i, int d, int periods, double* out) const;
  void append_ghosts(const double* in, std::size_t count, bool from_self);
};

/// The box's axes, the cutoff and the image layers in the exchange's terms (fractional
/// coordinates in a triclinic cell). ghost_layers throws RunError for a box far thinner than the
/// cutoff.
std::array<parallel::AxisSpan, 3> ghost_spans(const geometry::Box& box);
std::array<double, 3> ghost_cutoffs(const geometry::Box& box, double cutoff);
std::array<int, 3> ghost_layers(const geometry::Box& box, double cutoff);

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
