#pragma once
// Ghost layers of a grid block filled from the neighbouring ranks' interior cells (docs/parallel.md):
// along one axis at a time, each rank sends its `ghosts[axis]` layers next to each face to the
// neighbour across it and receives that neighbour's into its ghost layers (MPI_Sendrecv, low then
// high face). A periodic axis wraps through the rank grid (one rank along it is its own
// neighbour), so the exchange also makes the periodic images; at the edge of a non-periodic axis
// nothing is received and the method's own boundary condition fills the ghosts. Exchanging x,
// then y, then z — each slab spanning the ghosts of the axes already exchanged — fills the edge
// and corner ghosts too (values two exchanges away).
#include <vector>

#include "shockfield/parallel/communicator.hpp"
#include "shockfield/parallel/grid_layout.hpp"

namespace shockfield::parallel {

class HaloExchange {
 public:
  /// `grid`: a Cartesian communicator (RankGrid::comm()); `layout`: this rank's block, whose
  /// interior must be at least ghosts[a] cells along each exchanged axis a; `exchanged`: the axes
  /// whose ghosts come from the ranks (a method may keep an uncut axis to itself: the DBM fills
  /// a periodic axis of one rank as its serial run does, which also serves a 1-cell axis).
  HaloExchange(const Communicator& grid, const GridLayout& layout,
               const std::array<bool, 3>& exchanged = {true, true, true});

  /// Fills the ghost layers of `axis` in `data` (layout.components × layout.component_stride).
  void exchange(double* data, int axis) const;
  /// Whether the ghosts beyond side `high` (0 low, 1 high) of `axis` come from a rank (else from
  /// the method's boundary condition).
  bool has_neighbour(int axis, int high) const { return neighbours_[axis][high] != no_rank; }
  /// Doubles this rank sends in one exchange of every axis.
  std::size_t doubles_per_exchange() const;

 private:
  // The cells of the slab of `layers` layers from `first` along `axis` (see the header comment).
  std::size_t slab_size(int axis) const;
  void copy_slab(double* data, int axis, int first, std::vector<double>& buffer, bool to_buffer) const;

  Communicator comm_;
  GridLayout layout_;
  std::array<std::array<int, 2>, 3> neighbours_;
};

}  // namespace shockfield::parallel
