#pragma once
// The rolling-ball searchers of Xu et al. (2015) §3.2.3 on the SHT's generic searches:
//
//   MS3 `first_point_met` — a ball of radius r turning about an axis: the first point it meets.
//   MS1 `first_point_met` on `pivot_about_edge(A, B, C, r)` — the ball on triangle ABC (on the
//       side of its right-hand normal) turned about edge AB: the point that minimises the
//       rotation angle; the paper's MS1 is MS3 with this axis and start ("nearly the same").
//   CS1 `find_segment` — a segment of a segment tree by its two end points.
//
// The turning ball's centre runs on a circle c(θ) = m + ρ (cos θ x̂ + sin θ ŷ) about the axis
// ẑ = x̂ × ŷ through m, θ increasing by the right-hand rule about ẑ (for MS1, ẑ = (B − A)/|B − A|
// and x̂ along the start centre r_o − m: the ball rolls over AB away from C, as in the paper's
// x̂ = P_xy (r_o − r_A)/|…|, ŷ = ẑ × x̂). A point P at p = P − m is inside the ball when
//     |c(θ) − P|² < r²  ⇔  p_x cos θ + p_y sin θ > κ = (ρ² + |p|² − r²) / (2ρ),
// i.e. for θ ∈ (φ − α, φ + α) with φ = atan2(p_y, p_x), α = acos(κ / q), q = √(p_x² + p_y²): it is
// met at θ = φ − α, the value function (taken in [0, 2π)). The same inequality with P replaced by
// a sphere S (centre c_b, radius R) gives the angles at which the ball touches S, distance
// |c(θ) − c_b| ≤ r + R (the paper's tangent points mL, ML); every point in S is met at such an
// angle, so the first of them is the range bound m(b), S being the cube's region's circumsphere.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "shockfield/geometry/space_tree.hpp"
#include "shockfield/geometry/vec3.hpp"

namespace shockfield::geometry {

/// A ball of radius `ball_radius` whose centre turns on the circle c(θ) = centre + radius
/// (cos θ x + sin θ y) (x, y orthonormal, axis z = x × y).
struct PivotCircle {
  Point3 centre{};
  double radius = 0.0;
  Point3 x{}, y{}, z{};
  double ball_radius = 0.0;
};

/// MS3's ball: radius r, centred at `start` at θ = 0, turned about the line through `on_axis`
/// along `axis`. None when the axis is zero or `start` lies on the axis (the ball cannot turn).
std::optional<PivotCircle> pivot_about_axis(const Point3& on_axis, const Point3& axis,
                                            const Point3& start, double r);

/// MS1's ball: radius r through A, B and C, on the side of the normal (B − A) × (C − A), turned
/// about AB (away from C). None when no such ball exists (r below the circumradius of ABC, or
/// A, B, C collinear or coincident) or when r = |AB|/2 (the ball's centre on the axis).
std::optional<PivotCircle> pivot_about_edge(const Point3& a, const Point3& b, const Point3& c, double r);

/// Rotation angles within `kMetAtStart` below 0 count as 0: a point on the starting ball (four
/// cospherical points) is met at once, whatever the rounding of its angle (about 1e-15 rad).
inline constexpr double kMetAtStart = 1e-12;

/// The angle θ ∈ [0, 2π) at which the turning ball first meets p (the value function of MS1 and
/// MS3); +inf when it never does (p always outside, or inside from the start and never left).
double angle_met(const PivotCircle& pivot, const Point3& p);

/// A lower bound of angle_met over every point of the sphere (centre, radius): the first angle at
/// which the ball touches the sphere (m(b)); 0 when it touches it at the start, +inf never.
double first_angle_touching(const PivotCircle& pivot, const Point3& centre, double radius);

struct PivotHit {
  std::uint32_t id;
  double angle;
};

/// MS1/MS3: the point of `tree` (a tree of points) that the turning ball meets first, ignoring
/// the points in `exclude` (for MS1 the edge's A and B, which stay on the ball; C, left at θ = 0,
/// is met again only if the ball comes round to it); ties in angle go to the lower id. None when
/// the ball meets no point.
template <class Tree>
std::optional<PivotHit> first_point_met(const Tree& tree, const PivotCircle& pivot,
                                        std::span<const std::uint32_t> exclude = {}) {
  auto point = [&](std::uint32_t id) {
    Point3 lo, hi;
    tree.objects().bounds(id, lo, hi);
    return lo;
  };
  const auto found = tree.minimum_search(
      1,
      [&](const TreeCube<3>& cube) {
        // The circumsphere of the cube's region; M(b) = +inf: a cube may hold points the ball
        // never meets, so no finite upper bound holds for all of them.
        const double radius = std::sqrt(3.0) * (cube.half + cube.margin);
        return std::pair{first_angle_touching(pivot, cube.centre, radius),
                         std::numeric_limits<double>::infinity()};
      },
      [&](std::uint32_t id) {
        for (std::uint32_t e : exclude)
          if (e == id) return std::numeric_limits<double>::infinity();
        return angle_met(pivot, point(id));
      });
  if (found.empty()) return std::nullopt;
  return PivotHit{found.front().id, found.front().value};
}

/// Segments as pairs of indices into a point array: the objects of a segment tree.
template <int N>
struct SegmentsAdaptor {
  const std::vector<std::array<double, N>>* points;
  const std::vector<std::array<std::uint32_t, 2>>* ends;
  std::size_t size() const { return ends->size(); }
  void bounds(std::size_t i, std::array<double, N>& lo, std::array<double, N>& hi) const {
    const auto& p = (*points)[(*ends)[i][0]];
    const auto& q = (*points)[(*ends)[i][1]];
    for (int k = 0; k < N; ++k) {
      lo[k] = std::min(p[k], q[k]);
      hi[k] = std::max(p[k], q[k]);
    }
  }
};

/// CS1: the segment of `tree` (a tree over SegmentsAdaptor<N>) whose end points are the points
/// p1 and p2, in either order; the lowest such segment id when several, none when there is none.
/// maycontain(b): both points in the cube's region (the cube widened by its margin, which holds
/// every segment of the cube — tighter than the paper's circumsphere with the same meaning).
template <int N, class Tree>
std::optional<std::uint32_t> find_segment(const Tree& tree, std::uint32_t p1, std::uint32_t p2) {
  const auto& segments = tree.objects();
  const auto& a = (*segments.points)[p1];
  const auto& b = (*segments.points)[p2];
  std::optional<std::uint32_t> best;
  tree.conditional_search(
      [&](const TreeCube<N>& cube) {
        return cube.distance2_to(a) == 0.0 && cube.distance2_to(b) == 0.0;
      },
      [&](std::uint32_t id) {
        const auto& e = (*segments.ends)[id];
        return (e[0] == p1 && e[1] == p2) || (e[0] == p2 && e[1] == p1);
      },
      [&](std::uint32_t id) {
        if (!best || id < *best) best = id;
        return true;
      });
  return best;
}

}  // namespace shockfield::geometry
