#pragma once
// Cell list (the seed's "background grid + linked list", 000 §2.1): space is cut into cubic-ish
// cells at least `cell_size` wide, and each point is put in the cell that holds it. Points in
// CSR order (cell_start / cell_points) so a cell's points are contiguous.
#include <array>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield::geometry {

class CellList {
 public:
  /// Bins points[0, n) into cells of width >= cell_size over [lo, hi] (points outside are clamped
  /// into the edge cells).
  void build(const std::vector<Vec3>& points, std::size_t n, const Vec3& lo, const Vec3& hi,
             double cell_size);

  const std::array<int, 3>& dims() const { return dims_; }
  int cell_of(const Vec3& p) const;
  int cell_index(int ix, int iy, int iz) const { return (iz * dims_[1] + iy) * dims_[0] + ix; }
  std::array<int, 3> cell_coords(int c) const;
  /// Points of cell c: cell_points()[cell_start()[c] .. cell_start()[c+1]).
  const std::vector<int>& cell_start() const { return start_; }
  const std::vector<int>& cell_points() const { return points_; }

 private:
  Vec3 lo_ = Vec3::Zero();
  Vec3 inv_width_ = Vec3::Ones();
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_;
  std::vector<int> points_;
};

}  // namespace shockfield::geometry
