#include "shockfield/geometry/cell_list.hpp"

#include <algorithm>
#include <cmath>

namespace shockfield::geometry {

namespace {
// At most this many cells per point (and at least 64 cells may always be used).
constexpr double kMaxCellsPerPoint = 4.0;
}  // namespace

void CellList::build(const std::vector<Vec3>& points, std::size_t n, const Vec3& lo, const Vec3& hi,
                     double cell_size) {
  lo_ = lo;
  const double max_cells = std::max(kMaxCellsPerPoint * static_cast<double>(n), 64.0);
  Vec3 extent;
  for (int d = 0; d < 3; ++d) extent[d] = std::max(hi[d] - lo[d], cell_size);
  // Widen the cells uniformly until their number fits (a huge empty extent, a tiny cutoff).
  const double wanted = (extent / cell_size).array().floor().max(1.0).prod();
  if (wanted > max_cells) cell_size *= std::cbrt(wanted / max_cells);
  for (int d = 0; d < 3; ++d) {
    dims_[d] = std::max(static_cast<int>(std::floor(extent[d] / cell_size)), 1);
    inv_width_[d] = dims_[d] / std::max(extent[d], cell_size);
  }
  const int ncells = dims_[0] * dims_[1] * dims_[2];
  start_.resize(static_cast<std::size_t>(ncells) + 1);
  cell_.resize(n);
  points_.resize(n);
  UninitializedVector<int> fill(static_cast<std::size_t>(ncells));
  const auto sn = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (int c = 0; c <= ncells; ++c) start_[static_cast<std::size_t>(c)] = 0;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < sn; ++i) {
      const auto u = static_cast<std::size_t>(i);
      cell_[u] = cell_of(points[u]);
      points_[u] = 0;  // first touch here, not in the serial scatter below
    }
  }
  // Counting sort by cell: a point's index within its cell is its order among the cell's points.
  for (std::size_t i = 0; i < n; ++i) ++start_[static_cast<std::size_t>(cell_[i]) + 1];
  for (int c = 0; c < ncells; ++c) start_[c + 1] += start_[c];
#pragma omp parallel for schedule(static)
  for (int c = 0; c < ncells; ++c) fill[static_cast<std::size_t>(c)] = start_[static_cast<std::size_t>(c)];
  for (std::size_t i = 0; i < n; ++i) points_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_[i])]++)] = static_cast<int>(i);
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
