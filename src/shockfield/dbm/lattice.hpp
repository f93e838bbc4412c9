#pragma once
// The 2D Cartesian lattice of the DBM with two ghost layers on every side (enough for the NND
// stencil). Fields are structure-of-arrays: one contiguous array of cells per discrete velocity.
#include <cstddef>

namespace shockfield::dbm {

struct Lattice {
  /// Every case's lattice is 2D (a 1D problem is one row of cells): its totals, Σ over cells × dx
  /// dy, are per unit length of thickness (docs/conventions.md, "Per length and per area").
  static constexpr int dim = 2;
  static constexpr int ghosts = 2;
  int nx = 1, ny = 1;
  double dx = 1.0, dy = 1.0;

  int stride() const { return nx + 2 * ghosts; }
  std::size_t cells() const {
    return static_cast<std::size_t>(nx + 2 * ghosts) * static_cast<std::size_t>(ny + 2 * ghosts);
  }
  /// Storage index of cell (i, j); i in [−2, nx+1], j in [−2, ny+1].
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(j + ghosts) * static_cast<std::size_t>(stride()) +
           static_cast<std::size_t>(i + ghosts);
  }
  /// Cell-centre coordinates, the domain starting at 0.
  double x(int i) const { return (i + 0.5) * dx; }
  double y(int j) const { return (j + 0.5) * dy; }
};

}  // namespace shockfield::dbm
