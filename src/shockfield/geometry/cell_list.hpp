#pragma once
// Cell list (the paper's "background grid + linked list", Xu et al. 2015, §2.1): space is cut into cubic-ish
// cells at least `cell_size` wide, and each point is put in the cell that holds it. Points in
// CSR order (cell_start / cell_points) so a cell's points are contiguous, in increasing index
// order within a cell; cells are numbered x fastest, so a row of cells along x is one contiguous
// run of points.
#include <array>
#include <vector>

#include "shockfield/core/uninitialized_vector.hpp"

#include "shockfield/core/types.hpp"

namespace shockfield::geometry {

class CellList {
 public:
  /// Bins points[0, n) into cells of width >= cell_size over [lo, hi] (points outside are clamped
  /// into the edge cells). The cells are widened when needed so there are at most a few per point
  /// (a tiny cell_size over a large box would otherwise cost memory, not speed).
  void build(const std::vector<Vec3>& points, std::size_t n, const Vec3& lo, const Vec3& hi,
             double cell_size);

  const std::array<int, 3>& dims() const { return dims_; }
  /// Actual cell widths (>= the cell_size asked for).
  Vec3 width() const { return inv_width_.cwiseInverse(); }
  int cell_of(const Vec3& p) const;
  int cell_index(int ix, int iy, int iz) const { return (iz * dims_[1] + iy) * dims_[0] + ix; }
  std::array<int, 3> cell_coords(int c) const;
  /// Points of cell c: cell_points()[cell_start()[c] .. cell_start()[c+1]).
  const UninitializedVector<int>& cell_start() const { return start_; }
  const UninitializedVector<int>& cell_points() const { return points_; }
  /// The cell of each point binned by the last build (size n).
  const UninitializedVector<int>& point_cells() const { return cell_; }

 private:
  Vec3 lo_ = Vec3::Zero();
  Vec3 inv_width_ = Vec3::Ones();
  std::array<int, 3> dims_{1, 1, 1};
  // Filled by all threads where the work allows (first touch of fresh pages on one thread was a
  // serial part of every neighbour-list build).
  UninitializedVector<int> start_;
  UninitializedVector<int> points_;
  UninitializedVector<int> cell_;
};

}  // namespace shockfield::geometry
