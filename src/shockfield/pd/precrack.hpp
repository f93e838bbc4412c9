#pragma once
// Pre-cracks: every bond whose reference segment [x_i, x_j] crosses a crack is cut before the first
// step (the `[[crack]]` tables of a pd case, docs/pd.md; the rule in docs/theory/pd.md).
//   2D  a segment p–q: the bond is cut when x_i and x_j lie strictly on opposite sides of the line
//       pq and p and q do not lie strictly on one side of the bond's line (the crack reaches it).
//       Both signs are exact (geometry/predicates.hpp), so a point on the crack line keeps its
//       bonds and a crack along a lattice row cuts nothing.
//   3D  a planar polygon v_0..v_{n-1}: x_i and x_j strictly on opposite sides of its plane (exact
//       sign against three of its vertices) and the bond's crossing point inside the polygon
//       (crossing-number test in the plane, in floating point: a bond through an edge may go
//       either way).
// The bond models (pmb, lps) keep cut bonds as broken (they count in the damage); the
// correspondence models run on the family without them (they have no broken-bond state).
#include <array>
#include <cmath>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/types.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

class Crack {
 public:
  /// 2D: the segment from `vertices[0]` to `vertices[1]` (z = 0); 3D: the polygon of the corners
  /// in order (at least three, in one plane, not all on a line: read_crack checks it).
  Crack(int dim, std::vector<Vec3> vertices);

  /// Whether the bond from a to b crosses the crack (reference positions).
  bool cuts(const Vec3& a, const Vec3& b) const;
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const Vec3& lo() const { return lo_; }  ///< bounding box of the corners
  const Vec3& hi() const { return hi_; }
  /// Distance of x from the crack's line (2D) or plane (3D).
  double distance_to_support(const Vec3& x) const { return std::abs(unit_normal_.dot(x - vertices_.front())); }

 private:
  int dim_;
  std::vector<Vec3> vertices_;
  std::array<std::size_t, 3> span_{0, 1, 1};  ///< 3D: three corners spanning the plane
  Vec3 normal_ = Vec3::Zero();               ///< 3D: Newell's normal (not normalised)
  Vec3 unit_normal_ = Vec3::Zero();          ///< of the line (2D, in the xy plane) or plane (3D)
  Vec3 lo_, hi_;                             ///< bounding box of the corners
};

/// Reads one [[crack]] table of a `dim`-dimensional body: 2D `from = [x, y]`, `to = [x, y]`;
/// 3D `vertices = [x1, y1, z1, x2, y2, z2, ...]` (at least three corners, in one plane, not all
/// on a line). A 1D body has no crack.
Crack read_crack(const Config& t, int dim);

/// Whether the crack cuts some bond of the lattice of `counts` points `spacing` apart from
/// `origin` (as lattice_cloud places them) with horizon δ (build_family's rule), found without
/// building the body: only the points within δ of the crack's box and of its line or plane are
/// visited.
bool cuts_a_lattice_bond(const Crack& crack, int dim, const std::array<int, 3>& counts, double spacing, double horizon,
                         const Vec3& origin = Vec3::Zero());

/// Per bond of the family: 1 when some crack cuts it (both stored copies of a bond).
std::vector<unsigned char> cut_bonds(const PointCloud& cloud, const Family& family, const std::vector<Crack>& cracks);

/// The family without the bonds flagged in `cut` (the correspondence models' pre-crack).
Family without_bonds(const Family& family, const std::vector<unsigned char>& cut);

}  // namespace shockfield::pd
