#pragma once
// How a block of a structured grid is stored: `components` arrays (structure of arrays), each of
// `component_stride` values holding the interior cells and `ghosts[a]` ghost layers on both sides
// of axis a, x fastest. The DBM lattice (dbm/lattice.hpp) is {nx, ny, 1} with ghosts {2, 2, 0}.
#include <array>
#include <cstddef>

namespace shockfield::parallel {

struct GridLayout {
  std::array<int, 3> interior{1, 1, 1};
  std::array<int, 3> ghosts{0, 0, 0};
  int components = 1;
  std::size_t component_stride = 0;  ///< at least cells()

  int extent(int axis) const { return interior[axis] + 2 * ghosts[axis]; }
  std::size_t cells() const {
    return static_cast<std::size_t>(extent(0)) * static_cast<std::size_t>(extent(1)) *
           static_cast<std::size_t>(extent(2));
  }
  /// Storage index of cell (i, j, k) of component 0; i in [−ghosts[0], interior[0] + ghosts[0]).
  std::size_t at(int i, int j, int k) const {
    return (static_cast<std::size_t>(k + ghosts[2]) * static_cast<std::size_t>(extent(1)) +
            static_cast<std::size_t>(j + ghosts[1])) * static_cast<std::size_t>(extent(0)) +
           static_cast<std::size_t>(i + ghosts[0]);
  }
};

}  // namespace shockfield::parallel
