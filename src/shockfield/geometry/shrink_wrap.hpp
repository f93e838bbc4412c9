#pragma once
// Shrink-wrapped box faces as LAMMPS sets them. The margin is LAMMPS's Domain::small: 1e-4 × the
// box length when the box was created (create_box, read_data), kept fixed while the box changes;
// at every reset (neighbour rebuilds, write_data) a shrink-wrapped dimension becomes the atoms'
// extent padded by it (Domain::reset_box).
#include <algorithm>
#include <span>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"

namespace shockfield::geometry {

/// LAMMPS's shrink-wrap margin of a box created with these bounds: 1e-4 × each length.
inline Vec3 shrink_margin(const Box& box) { return 1e-4 * box.length(); }

/// Sets each shrink-wrapped dimension of `box` to the extent of `x` padded by `margin`; other
/// dimensions, and any dimension when `x` is empty, are left as they are.
inline void shrink_wrap(Box& box, std::span<const Vec3> x, const Vec3& margin) {
  if (x.empty()) return;
  for (int d = 0; d < 3; ++d) {
    if (box.boundary[d] != Boundary::shrink) continue;
    double lo = x[0][d], hi = lo;
    for (const Vec3& p : x) {
      lo = std::min(lo, p[d]);
      hi = std::max(hi, p[d]);
    }
    box.lo[d] = lo - margin[d];
    box.hi[d] = hi + margin[d];
  }
}

}  // namespace shockfield::geometry
