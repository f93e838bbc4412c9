#pragma once
// A grid of 1, 2 or 3 dimensions with cubic cells of size dx; node (i, j, k) at (i dx, j dx, k dx),
// stored x fastest (i + nx (j + ny k)); unused dimensions have n = 1. Each axis is periodic
// (length n dx) or bounded by walls on its first and last nodes (length (n − 1) dx):
// - neumann: no flux through the wall, the ghost node beyond a wall mirrors the node inside it
//   (ξ₋₁ = ξ₁), second-order accurate at the wall;
// - dirichlet: the wall nodes hold fixed values (`fixed[d]`, lo and hi) and are never updated.
#include <array>
#include <cstddef>

namespace shockfield::phasefield {

enum class Boundary { periodic, neumann, dirichlet };

struct Grid {
  int dim = 1;
  std::array<int, 3> n{1, 1, 1};
  double dx = 1.0;
  std::array<Boundary, 3> boundary{Boundary::periodic, Boundary::periodic, Boundary::periodic};
  std::array<std::array<double, 2>, 3> fixed{};  ///< dirichlet values on the lo and hi walls

  std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  double cell_volume() const {
    double v = 1.0;
    for (int d = 0; d < dim; ++d) v *= dx;
    return v;
  }
  bool periodic(int d) const { return boundary[d] == Boundary::periodic; }
  bool all_periodic() const {
    for (int d = 0; d < dim; ++d)
      if (!periodic(d)) return false;
    return true;
  }
  /// The extent of axis d: n dx periodic (node n is node 0 again), (n − 1) dx between walls.
  double length(int d) const { return (periodic(d) ? n[d] : n[d] - 1) * dx; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * (j + static_cast<std::size_t>(n[1]) * k);
  }
  /// The neighbour of node i along axis d in direction step = ±1: wrapped on a periodic axis,
  /// mirrored at a wall (the ghost ξ₋₁ = ξ₁ of a zero-flux wall; a dirichlet wall node is not
  /// updated, so its mirrored neighbour is never used).
  int neighbour(int d, int i, int step) const {
    const int j = i + step;
    if (j >= 0 && j < n[d]) return j;
    if (periodic(d)) return j < 0 ? n[d] - 1 : 0;
    return i - step;
  }
};

}  // namespace shockfield::phasefield
