#pragma once
// A periodic grid of 1, 2 or 3 dimensions with cubic cells of size dx; node (i, j, k) at
// (i dx, j dx, k dx), stored x fastest (i + nx (j + ny k)); unused dimensions have n = 1.
#include <array>
#include <cstddef>

namespace shockfield::phasefield {

struct Grid {
  int dim = 1;
  std::array<int, 3> n{1, 1, 1};
  double dx = 1.0;

  std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  double cell_volume() const {
    double v = 1.0;
    for (int d = 0; d < dim; ++d) v *= dx;
    return v;
  }
  double length(int d) const { return n[d] * dx; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * (j + static_cast<std::size_t>(n[1]) * k);
  }
  /// Largest stable explicit step of the diffusion part, dx²/(2 dim D).
  double explicit_limit(double D) const { return dx * dx / (2.0 * dim * D); }
};

}  // namespace shockfield::phasefield
