#include "shockfield/geometry/cell_list.hpp"

#include <algorithm>
#include <cmath>

namespace shockfield::geometry {

void CellList::build(const std::vector<Vec3>& points, std::size_t n, const Vec3& lo, const Vec3& hi,
                     double cell_size) {
  lo_ = lo;
  for (int d = 0; d < 3; ++d) {
    const double extent = std::max(hi[d] - lo[d], cell_size);
    // Cap the cell count so a huge empty extent (shrink-wrapped box, lone atom) stays cheap.
    dims_[d] = std::clamp(static_cast<int>(std::floor(extent / cell_size)), 1, 1024);
    inv_width_[d] = dims_[d] / extent;
  }
  const int ncells = dims_[0] * dims_[1] * dims_[2];
  start_.assign(static_cast<std::size_t>(ncells) + 1, 0);
  std::vector<int> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = cell_of(points[i]);
    ++start_[static_cast<std::size_t>(cell[i]) + 1];
  }
  for (int c = 0; c < ncells; ++c) start_[c + 1] += start_[c];
  points_.resize(n);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) points_[fill[cell[i]]++] = static_cast<int>(i);
}

int CellList::cell_of(const Vec3& p) const {
  int c[3];
  for (int d = 0; d < 3; ++d)
    c[d] = std::clamp(static_cast<int>(std::floor((p[d] - lo_[d]) * inv_width_[d])), 0, dims_[d] - 1);
  return cell_index(c[0], c[1], c[2]);
}

std::array<int, 3> CellList::cell_coords(int c) const {
  return {c % dims_[0], (c / dims_[0]) % dims_[1], c / (dims_[0] * dims_[1])};
}

}  // namespace shockfield::geometry
