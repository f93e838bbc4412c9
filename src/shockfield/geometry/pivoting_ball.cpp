// The pivoting rolling ball (pivoting_ball.hpp).
#include "shockfield/geometry/pivoting_ball.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/pivot_searches.hpp"
#include "shockfield/geometry/space_tree_queries.hpp"

namespace shockfield::geometry {
namespace {

auto adaptor_of(const std::vector<Point3>& points) {
  return points_adaptor<3>(points.size(), [&points](std::size_t i, int k) { return points[i][k]; });
}
using PointTree = SpaceTree<3, decltype(adaptor_of(std::declval<const std::vector<Point3>&>()))>;

Point3 centre_at(const PivotCircle& c, double angle) {
  return add_scaled(add_scaled(c.centre, c.x, c.radius * std::cos(angle)), c.y,
                    c.radius * std::sin(angle));
}

/// Step I: the seed triangle, oriented with its normal towards the ball.
std::array<std::uint32_t, 3> seed_triangle(const PointTree& tree, const std::vector<Point3>& x,
                                           double r) {
  const auto largest_x = tree.minimum_search(
      1,
      [](const TreeCube<3>& cube) {
        return std::pair{-cube.hi(0), -cube.lo(0)};
      },
      [&](std::uint32_t id) { return -x[id][0]; });
  const std::uint32_t p1 = largest_x.front().id;
  auto fail = [&](const char* what) {
    return InputError(
        fmt::format("pivoting ball of radius {}: {} (the ball on the point of "
                    "largest x meets too few points; give a larger radius)",
                    r, what));
  };
  const Point3 start = add_scaled(x[p1], {1.0, 0.0, 0.0}, r);
  const auto turn1 = pivot_about_axis(x[p1], {0.0, 0.0, 1.0}, start, r);
  const std::array<std::uint32_t, 1> not_p1{p1};
  const auto p2 = first_point_met(tree, *turn1, not_p1);
  if (!p2) throw fail("no second point met turning about z");
  const Point3 centre1 = centre_at(*turn1, p2->angle);
  const auto turn2 = pivot_about_axis(x[p1], sub(x[p2->id], x[p1]), centre1, r);
  const std::array<std::uint32_t, 2> not_p1_p2{p1, p2->id};
  const auto p3 = turn2 ? first_point_met(tree, *turn2, not_p1_p2) : std::nullopt;
  if (!p3) throw fail("no third point met turning about P1P2");
  const Point3 centre2 = centre_at(*turn2, p3->angle);
  const Point3 normal = cross(sub(x[p2->id], x[p1]), sub(x[p3->id], x[p1]));
  if (dot(normal, sub(centre2, x[p1])) < 0.0) return {p1, p3->id, p2->id};
  return {p1, p2->id, p3->id};
}

/// The front: directed edges (u, v) of made triangles whose other side is still open, with the
/// triangle's third point, in a segment tree for CS1.
class Front {
 public:
  explicit Front(const std::vector<Point3>& points) : segments_{&points, &ends_}, tree_(segments_) {}
  void add(std::uint32_t u, std::uint32_t v, std::uint32_t third) {
    ends_.push_back({u, v});
    opposite_.push_back(third);
    const auto id = static_cast<std::uint32_t>(ends_.size() - 1);
    tree_.insert(id);
    pending_.push_back(id);
  }
  /// Edge (u, v) of a new triangle: closes the front's (v, u) when there (CS1), else opens.
  void meet(std::uint32_t u, std::uint32_t v, std::uint32_t third) {
    const auto twin = find_segment<3>(tree_, u, v);
    if (twin && ends_[*twin][0] == v) {
      tree_.remove(*twin);
      return;
    }
    add(u, v, third);
  }
  /// Takes an open edge off the front: {u, v, third}; false when the front is empty.
  bool take(std::array<std::uint32_t, 3>& edge) {
    while (!pending_.empty()) {
      const std::uint32_t id = pending_.back();
      pending_.pop_back();
      if (!tree_.remove(id)) continue;  // closed meanwhile
      edge = {ends_[id][0], ends_[id][1], opposite_[id]};
      return true;
    }
    return false;
  }

 private:
  std::vector<std::array<std::uint32_t, 2>> ends_;
  std::vector<std::uint32_t> opposite_;
  SegmentsAdaptor<3> segments_;
  SpaceTree<3, SegmentsAdaptor<3>> tree_;
  std::vector<std::uint32_t> pending_;
};

/// The points moved by 10⁻⁹ of the bounding box's largest side in a direction drawn from each
/// point's index (splitmix64): exact ties — four or more points on one ball, as on a lattice,
/// where the pivot would otherwise make crossing triangles — become distinct angles, all
/// decided on one moved point set, so the triangles stay consistent.
std::vector<Point3> moved_off_ties(const std::vector<Point3>& points) {
  double extent = 0.0;
  for (int k = 0; k < 3; ++k) {
    const auto [lo, hi] = std::minmax_element(
        points.begin(), points.end(), [k](const Point3& p, const Point3& q) { return p[k] < q[k]; });
    extent = std::max(extent, (*hi)[k] - (*lo)[k]);
  }
  const double step = 1e-9 * extent;
  std::vector<Point3> moved = points;
  for (std::size_t i = 0; i < moved.size(); ++i) {
    std::uint64_t z = 0x9e3779b97f4a7c15ull * (i + 1);
    for (int k = 0; k < 3; ++k) {
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      z ^= z >> 31;
      moved[i][k] += step * (static_cast<double>(z >> 11) * 0x1.0p-53 * 2.0 - 1.0);
    }
  }
  return moved;
}

/// The points to pivot on: the first of each set of equal points (MS2 finds an equal point
/// already held), so that no triangle is made between copies of one point.
std::vector<std::uint32_t> distinct_points(const std::vector<Point3>& points) {
  const auto adaptor = adaptor_of(points);
  PointTree tree(adaptor);
  std::vector<std::uint32_t> keep;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (tree.size() > 0 && nearest<3>(tree, points[i]).distance == 0.0) continue;
    tree.insert(i);
    keep.push_back(i);
  }
  return keep;
}

}  // namespace

TriangleSurface pivoting_ball_surface(const std::vector<Point3>& points, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError(
        fmt::format("rolling-ball radius must be a positive finite length, got {}", radius));
  for (std::size_t i = 0; i < points.size(); ++i)
    for (double c : points[i])
      if (!std::isfinite(c))
        throw InputError(fmt::format("point {} has a non-finite coordinate", i));
  const auto distinct = distinct_points(points);
  if (distinct.size() < 3)
    throw InputError(fmt::format("{} distinct points: a pivoting-ball surface needs at least 3",
                                 distinct.size()));
  const std::vector<Point3> moved = moved_off_ties(points);  // every decision on these
  const auto adaptor = adaptor_of(moved);
  PointTree tree(adaptor);
  for (std::uint32_t i : distinct) tree.insert(i);
  TriangleSurface s;
  s.points = points;
  std::set<std::array<std::uint32_t, 3>> made;  // vertex sets, to refuse a triangle made twice
  auto key = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::array<std::uint32_t, 3> k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
  };
  const auto seed = seed_triangle(tree, moved, radius);
  s.triangles.push_back({std::int32_t(seed[0]), std::int32_t(seed[1]), std::int32_t(seed[2])});
  made.insert(key(seed[0], seed[1], seed[2]));
  Front front(moved);
  for (int k = 0; k < 3; ++k) front.add(seed[k], seed[(k + 1) % 3], seed[(k + 2) % 3]);
  std::size_t stuck = 0, twice = 0;
  std::array<std::uint32_t, 3> edge;
  while (front.take(edge)) {
    const auto [a, b, c] = edge;
    const auto pivot = pivot_about_edge(moved[a], moved[b], moved[c], radius);
    const std::array<std::uint32_t, 2> ab{a, b};
    const auto hit = pivot ? first_point_met(tree, *pivot, ab) : std::nullopt;
    if (!hit) {
      ++stuck;
      continue;
    }
    const std::uint32_t p = hit->id;
    if (!made.insert(key(b, a, p)).second) {
      ++twice;
      continue;
    }
    s.triangles.push_back({std::int32_t(b), std::int32_t(a), std::int32_t(p)});
    front.meet(a, p, b);
    front.meet(p, b, a);
    if (s.triangles.size() > 4 * points.size() + 16)
      throw InputError(
          fmt::format("pivoting ball of radius {}: more than {} triangles, the ball "
                      "does not close a surface",
                      radius, 4 * points.size() + 16));
  }
  measure_surface(s);
  if (stuck > 0 || twice > 0 || !s.manifold)
    throw InputError(fmt::format(
        "pivoting ball of radius {}: the surface does not close ({} edges about which the ball "
        "meets no point or has no room, {} triangles made twice, {}); give a radius between the "
        "point spacing and the smallest feature, or use the Delaunay surface",
        radius, stuck, twice, s.manifold ? "edge-manifold" : "not edge-manifold"));
  return s;
}

}  // namespace shockfield::geometry
