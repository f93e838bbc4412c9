#include "shockfield/pd/precrack.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "shockfield/geometry/predicates.hpp"

namespace shockfield::pd {
namespace {

int orient2(const Vec3& p, const Vec3& q, const Vec3& r) {
  return geometry::orient<2>({p.data(), q.data(), r.data()});
}

// Three corners spanning the polygon's plane: v_0, the corner farthest from it, and the corner
// farthest from the line through those two (so that the exact side test is well conditioned).
std::array<std::size_t, 3> spanning_corners(const std::vector<Vec3>& v) {
  std::size_t far = 1, third = 2;
  for (std::size_t k = 1; k < v.size(); ++k)
    if ((v[k] - v[0]).squaredNorm() > (v[far] - v[0]).squaredNorm()) far = k;
  const Vec3 axis = (v[far] - v[0]).normalized();
  double best = -1.0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const double d = (v[k] - v[0]).cross(axis).squaredNorm();
    if (d > best) best = d, third = k;
  }
  return {0, far, third};
}

// Newell's normal of a polygon (not normalised; zero when its corners are on one line).
Vec3 newell_normal(const std::vector<Vec3>& v) {
  Vec3 n = Vec3::Zero();
  for (std::size_t k = 0; k < v.size(); ++k) n += v[k].cross(v[(k + 1) % v.size()]);
  return n;
}

// Crossing-number test of x against the polygon, both projected on the coordinate plane that
// drops the normal's largest component.
bool inside_polygon(const std::vector<Vec3>& v, const Vec3& normal, const Vec3& x) {
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int a = (drop + 1) % 3, b = (drop + 2) % 3;
  bool inside = false;
  for (std::size_t k = 0, l = v.size() - 1; k < v.size(); l = k++) {
    const Vec3 &p = v[k], &q = v[l];
    if ((p[b] > x[b]) != (q[b] > x[b]) && x[a] < p[a] + (q[a] - p[a]) * (x[b] - p[b]) / (q[b] - p[b]))
      inside = !inside;
  }
  return inside;
}

}  // namespace

Crack::Crack(int dim, std::vector<Vec3> vertices) : dim_(dim), vertices_(std::move(vertices)) {
  lo_ = hi_ = vertices_.front();
  for (const Vec3& v : vertices_) lo_ = lo_.cwiseMin(v), hi_ = hi_.cwiseMax(v);
  if (dim_ == 3) span_ = spanning_corners(vertices_), normal_ = newell_normal(vertices_);
  const Vec3 along = vertices_[1] - vertices_[0];
  unit_normal_ = (dim_ == 3 ? normal_ : Vec3(-along.y(), along.x(), 0.0)).normalized();
}

bool Crack::cuts(const Vec3& a, const Vec3& b) const {
  // A bond whose box misses the crack's box cannot cross it.
  if (((a.cwiseMax(b)).array() < lo_.array()).any() || ((a.cwiseMin(b)).array() > hi_.array()).any()) return false;
  if (dim_ == 2) {
    const Vec3 &p = vertices_[0], &q = vertices_[1];
    if (orient2(p, q, a) * orient2(p, q, b) >= 0) return false;
    return orient2(a, b, p) * orient2(a, b, q) <= 0;
  }
  const Vec3 &p = vertices_[span_[0]], &q = vertices_[span_[1]], &r = vertices_[span_[2]];
  const int side_a = geometry::orient<3>({p.data(), q.data(), r.data(), a.data()});
  const int side_b = geometry::orient<3>({p.data(), q.data(), r.data(), b.data()});
  if (side_a * side_b >= 0) return false;
  const double da = normal_.dot(a - p), db = normal_.dot(b - p);
  return inside_polygon(vertices_, normal_, a + (da / (da - db)) * (b - a));
}

// Corners within 1e50 m, as point files (geometry/point_file.cpp): the exact predicates multiply up
// to three coordinate differences, which stay finite.
const Range kCoordinate = Range::closed(-1e50, 1e50);

Crack read_crack(const Config& t, int dim) {
  if (dim == 1) t.fail("from", "a 1D bar has no pre-crack (cracks need a 2D or 3D body)");
  std::vector<Vec3> v;
  if (dim == 2) {
    for (const char* key : {"from", "to"}) {
      const auto p = t.get_doubles(key, 2, kCoordinate);
      v.emplace_back(p[0], p[1], 0.0);
    }
    if (v[0] == v[1]) t.fail("to", "the crack's two ends are the same point (expected a segment)");
    return Crack(dim, std::move(v));
  }
  const auto xyz = t.get_doubles("vertices", 0, kCoordinate);
  if (xyz.size() % 3 != 0 || xyz.size() < 9)
    t.fail("vertices", fmt::format("{} numbers; expected the x, y, z of at least three corners (a multiple of 3)",
                                   xyz.size()));
  for (std::size_t k = 0; k < xyz.size(); k += 3) v.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
  const Vec3 n = newell_normal(v);
  double size = 0.0;
  for (const Vec3& x : v) size = std::max(size, (x - v[0]).norm());
  if (!(n.norm() > 1e-12 * size * size))
    t.fail("vertices", "the corners lie on one line (expected a polygon spanning a plane)");
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::abs(n.normalized().dot(v[k] - v[0])) > 1e-9 * size)
      t.fail("vertices", fmt::format("corner {} is off the plane of the others (expected a planar polygon)", k + 1));
  return Crack(dim, std::move(v));
}

bool cuts_a_lattice_bond(const Crack& crack, int dim, const std::array<int, 3>& counts, double spacing, double horizon,
                         const Vec3& origin) {
  const int reach = static_cast<int>(std::floor(horizon / spacing * (1.0 + 1e-9)));
  const double cut2 = horizon * horizon * (1.0 + 1e-12);  // build_family's cut-off
  std::array<int, 3> first{0, 0, 0}, last{0, 0, 0}, span{0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    const double lo = std::floor((crack.lo()[d] - origin[d] - horizon) / spacing),
                 hi = std::ceil((crack.hi()[d] - origin[d] + horizon) / spacing);
    first[d] = static_cast<int>(std::clamp(lo, 0.0, counts[d] - 1.0));
    last[d] = static_cast<int>(std::clamp(hi, 0.0, counts[d] - 1.0));
    span[d] = reach;
  }
  const auto at = [&](int i, int j, int k) { return Vec3(origin + spacing * Vec3(i, j, k)); };
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i) {
        if (crack.distance_to_support(at(i, j, k)) > horizon * (1.0 + 1e-9)) continue;  // no bond reaches it
        for (int c = -span[2]; c <= span[2]; ++c)
          for (int b = -span[1]; b <= span[1]; ++b)
            for (int a = -span[0]; a <= span[0]; ++a) {
              const int p = i + a, q = j + b, r = k + c;
              if (p < 0 || q < 0 || r < 0 || p >= counts[0] || q >= counts[1] || r >= counts[2]) continue;
              const Vec3 x = at(i, j, k), y = at(p, q, r);
              if ((y - x).squaredNorm() <= cut2 && crack.cuts(x, y)) return true;
            }
      }
  return false;
}

std::vector<unsigned char> cut_bonds(const PointCloud& cloud, const Family& family, const std::vector<Crack>& cracks) {
  std::vector<unsigned char> cut(family.bonds(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (int b = family.begin(i); b < family.end(i); ++b)
      for (const Crack& crack : cracks)
        if (crack.cuts(cloud.x[i], cloud.x[static_cast<std::size_t>(family.neighbor[b])])) {
          cut[static_cast<std::size_t>(b)] = 1;
          break;
        }
  return cut;
}

Family without_bonds(const Family& family, const std::vector<unsigned char>& cut) {
  Family kept;
  kept.horizon = family.horizon;
  kept.offset.push_back(0);
  for (std::size_t i = 0; i + 1 < family.offset.size(); ++i) {
    for (int b = family.begin(i); b < family.end(i); ++b) {
      if (cut[static_cast<std::size_t>(b)]) continue;
      kept.neighbor.push_back(family.neighbor[b]);
      kept.length.push_back(family.length[b]);
      kept.volume_scale.push_back(family.volume_scale[b]);
    }
    kept.offset.push_back(static_cast<int>(kept.neighbor.size()));
  }
  return kept;
}

}  // namespace shockfield::pd
