#include "shockfield/geometry/neighbor_list.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/cell_list.hpp"

namespace shockfield::geometry {
namespace {

// Bins are half the list cutoff wide (LAMMPS's default binsize): a point's candidates lie in a
// 5×5×5 block of bins, 15.6 rc³, against 27 rc³ for bins one cutoff wide.
constexpr double kBinsPerCutoff = 2.0;

// Of the two periodic copies of a crossing pair, keep the one whose ghost lies above (larger z,
// then y, then x). Branch-free: the candidates of a point are tested without a jump each.
inline bool ghost_above(const Vec3& xi, const Vec3& xj) {
  return (xj.z() > xi.z()) | ((xj.z() == xi.z()) & ((xj.y() > xi.y()) | ((xj.y() == xi.y()) & (xj.x() > xi.x()))));
}

// One row of the stencil: bins (dx, dy, dz) for |dx| <= reach_x; rows whose nearest bin is
// beyond the cutoff are left out.
struct StencilRow {
  int dy, dz, reach_x;
};

std::vector<StencilRow> stencil_rows(const CellList& cells, double cutoff) {
  const Vec3 w = cells.width();
  auto reach = [&](int d) { return static_cast<int>(std::ceil(cutoff / w[d])); };
  // Smallest separation of two points whose bins are `steps` apart along a dimension of width wd.
  auto gap = [](int steps, double wd) { return std::max(std::abs(steps) - 1, 0) * wd; };
  std::vector<StencilRow> rows;
  for (int dz = -reach(2); dz <= reach(2); ++dz)
    for (int dy = -reach(1); dy <= reach(1); ++dy) {
      const double left = cutoff * cutoff - gap(dz, w.z()) * gap(dz, w.z()) - gap(dy, w.y()) * gap(dy, w.y());
      if (left <= 0) continue;
      rows.push_back({dy, dz, std::min(reach(0), 1 + static_cast<int>(std::ceil(std::sqrt(left) / w.x())))});
    }
  return rows;
}

// The points' bounding box; false when a coordinate is not finite (min/max would skip a NaN and
// an infinity would make the cell grid meaningless).
bool bounding_box(const std::vector<Vec3>& points, Vec3& lo, Vec3& hi) {
  double xlo = 1e300, ylo = 1e300, zlo = 1e300, xhi = -1e300, yhi = -1e300, zhi = -1e300;
  bool finite = true;
  const auto n = static_cast<std::ptrdiff_t>(points.size());
#pragma omp parallel for schedule(static) reduction(min : xlo, ylo, zlo) reduction(max : xhi, yhi, zhi) reduction(&& : finite)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Vec3& p = points[static_cast<std::size_t>(i)];
    finite = finite && std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
    xlo = std::min(xlo, p.x()); ylo = std::min(ylo, p.y()); zlo = std::min(zlo, p.z());
    xhi = std::max(xhi, p.x()); yhi = std::max(yhi, p.y()); zhi = std::max(zhi, p.z());
  }
  lo = n == 0 ? Vec3::Zero() : Vec3(xlo, ylo, zlo);
  hi = n == 0 ? Vec3::Zero() : Vec3(xhi, yhi, zhi);
  return finite;
}

}  // namespace

void build_neighbor_list(const std::vector<Vec3>& points, std::size_t nlocal, double cutoff,
                         bool half, NeighborList& list) {
  Vec3 lo, hi;
  if (!bounding_box(points, lo, hi) || !std::isfinite(cutoff))
    throw RunError("neighbour list: a position is not finite (the run blew up: a time step too large for the "
                   "forces, or parameters out of their physical range)");
  CellList cells;
  cells.build(points, points.size(), lo, hi, cutoff / kBinsPerCutoff);
  const auto dims = cells.dims();
  const auto rows = stencil_rows(cells, cutoff);
  const double cut2 = cutoff * cutoff;
  const int* start = cells.cell_start().data();
  const int* binned = cells.cell_points().data();
  const int own = static_cast<int>(nlocal);

  // Each thread lists the neighbours of a contiguous range of owned points into its own buffer
  // (in point order, each point's neighbours in stencil order); thread 0's buffer, with room for
  // the whole list, then receives the others' and becomes the list. The ranges are fixed by
  // nlocal and the thread count, the per-point lists by the positions alone, so the list does
  // not depend on the thread count. The previous list is released first: the two never coexist.
  const int nthreads = omp_get_max_threads();
  // Room for the previous list's mean count per point (lists change little between builds).
  const std::size_t per_point = list.nlocal() == 0 ? 16 : list.pairs() / list.nlocal() + 4;
  UninitializedVector<int>().swap(list.neighbors);
  std::vector<UninitializedVector<int>> chunk_neighbors(static_cast<std::size_t>(nthreads));
  list.offset.resize(nlocal + 1);
  list.offset[0] = 0;
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    const std::size_t begin = nlocal * t / nthreads, end = nlocal * (t + 1) / nthreads;
    UninitializedVector<int>& out = chunk_neighbors[static_cast<std::size_t>(t)];
    if (t == 0) out.reserve(nlocal * per_point);
    out.resize((end - begin) * per_point);
    std::size_t n = 0;  // neighbours listed so far; out holds room for every candidate
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 xi = points[i];
      const auto c = cells.cell_coords(cells.point_cells()[i]);
      const int si = static_cast<int>(i);
      for (const StencilRow& row : rows) {
        const int cz = c[2] + row.dz, cy = c[1] + row.dy;
        if (cz < 0 || cz >= dims[2] || cy < 0 || cy >= dims[1]) continue;
        // Bins along x are consecutive, so the row is one run of points.
        const int first = start[cells.cell_index(std::max(c[0] - row.reach_x, 0), cy, cz)];
        const int last = start[cells.cell_index(std::min(c[0] + row.reach_x, dims[0] - 1), cy, cz) + 1];
        if (n + static_cast<std::size_t>(last - first) > out.size())
          out.resize(2 * (n + static_cast<std::size_t>(last - first)));
        int* o = out.data();
        // Every candidate is written and kept by advancing n (no unpredictable branches).
        for (int k = first; k < last; ++k) {
          const int j = binned[k];
          const Vec3& xj = points[static_cast<std::size_t>(j)];
          const bool wanted = half ? ((j < own) & (j > si)) | ((j >= own) & ghost_above(xi, xj)) : j != si;
          o[n] = j;
          n += static_cast<std::size_t>(wanted & ((xj - xi).squaredNorm() < cut2));
        }
      }
      list.offset[i + 1] = static_cast<std::int64_t>(n);  // within the chunk for now
    }
    out.resize(n);
#pragma omp barrier
#pragma omp single
    {
      // Chunk-relative ends to global offsets, chunk by chunk.
      std::int64_t base = 0;
      for (int u = 0; u < nthreads; ++u) {
        const std::size_t b = nlocal * u / nthreads, e = nlocal * (u + 1) / nthreads;
        for (std::size_t i = b; i < e; ++i) list.offset[i + 1] += base;
        base += static_cast<std::int64_t>(chunk_neighbors[static_cast<std::size_t>(u)].size());
      }
      chunk_neighbors[0].resize(static_cast<std::size_t>(base));
    }
    if (t > 0) std::copy(out.begin(), out.end(), chunk_neighbors[0].begin() + list.offset[begin]);
  }
  list.neighbors.swap(chunk_neighbors[0]);
  list.cutoff = cutoff;
  list.half = half;
}

}  // namespace shockfield::geometry
