#include "shockfield/geometry/neighbor_list.hpp"

#include <omp.h>

#include <algorithm>

#include "shockfield/geometry/cell_list.hpp"

namespace shockfield::geometry {
namespace {
// Of the two periodic copies of a crossing pair, keep the one whose ghost lies above.
inline bool ghost_above(const Vec3& xi, const Vec3& xj) {
  if (xj.z() != xi.z()) return xj.z() > xi.z();
  if (xj.y() != xi.y()) return xj.y() > xi.y();
  return xj.x() > xi.x();
}
}  // namespace

void build_neighbor_list(const std::vector<Vec3>& points, std::size_t nlocal, double cutoff,
                         bool half, NeighborList& list) {
  const std::size_t n = points.size();
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(points[i]);
    hi = hi.cwiseMax(points[i]);
  }
  if (n == 0) lo = hi = Vec3::Zero();
  CellList cells;
  cells.build(points, n, lo, hi, cutoff);
  const auto dims = cells.dims();
  const double cut2 = cutoff * cutoff;

  // Pass 1: neighbours of each point into per-point scratch, in owned-point order per thread
  // chunk; pass 2: CSR concatenation. Static schedule keeps the order thread-count independent.
  const int nthreads = omp_get_max_threads();
  std::vector<std::vector<int>> chunk_neighbors(nthreads);
  std::vector<std::int64_t> count(nlocal + 1, 0);
  std::vector<std::size_t> chunk_begin(nthreads + 1, 0);
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    const std::size_t begin = nlocal * t / nthreads, end = nlocal * (t + 1) / nthreads;
    chunk_begin[t] = begin;
    std::vector<int>& out = chunk_neighbors[t];
    out.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 xi = points[i];
      const auto c = cells.cell_coords(cells.cell_of(xi));
      const std::size_t before = out.size();
      for (int dz = -1; dz <= 1; ++dz) {
        const int cz = c[2] + dz;
        if (cz < 0 || cz >= dims[2]) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          const int cy = c[1] + dy;
          if (cy < 0 || cy >= dims[1]) continue;
          for (int dx = -1; dx <= 1; ++dx) {
            const int cx = c[0] + dx;
            if (cx < 0 || cx >= dims[0]) continue;
            const int cell = cells.cell_index(cx, cy, cz);
            for (int k = cells.cell_start()[cell]; k < cells.cell_start()[cell + 1]; ++k) {
              const int j = cells.cell_points()[k];
              if (static_cast<std::size_t>(j) == i) continue;
              if (half) {
                if (static_cast<std::size_t>(j) < nlocal) {
                  if (static_cast<std::size_t>(j) < i) continue;
                } else if (!ghost_above(xi, points[j])) {
                  continue;
                }
              }
              if ((points[j] - xi).squaredNorm() < cut2) out.push_back(j);
            }
          }
        }
      }
      // Sorted neighbours: memory-friendly access and an order independent of cell layout.
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
      count[i + 1] = static_cast<std::int64_t>(out.size() - before);
    }
  }
  chunk_begin[nthreads] = nlocal;
  list.offset.assign(nlocal + 1, 0);
  for (std::size_t i = 0; i < nlocal; ++i) list.offset[i + 1] = list.offset[i] + count[i + 1];
  list.neighbors.resize(static_cast<std::size_t>(list.offset[nlocal]));
  for (int t = 0; t < nthreads; ++t)
    std::copy(chunk_neighbors[t].begin(), chunk_neighbors[t].end(),
              list.neighbors.begin() + list.offset[chunk_begin[t]]);
  list.cutoff = cutoff;
  list.half = half;
}

}  // namespace shockfield::geometry
