// The rolling-ball searchers MS1, MS3 (first point met by a turning ball) and CS1 (a segment by
// its end points) on the SHT against brute force over every point or segment: uniform random,
// Gaussian blobs and a simple cubic lattice (exact ties: many points met at the same angle,
// resolved by the lower id). Tolerance: none — the tree evaluates the same value function as the
// brute force, so id and angle must be identical. Plus the angle against a closed form, the
// empty-ball property of an MS1 pivot, and the "none" results.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shockfield/geometry/pivot_searches.hpp"
#include "shockfield/geometry/space_tree_queries.hpp"

namespace shockfield::geometry {
namespace {

using Points = std::vector<Point3>;

auto adaptor_of(const Points& pts) {
  return points_adaptor<3>(pts.size(), [&pts](std::size_t i, int k) { return pts[i][k]; });
}
using PointTree = SpaceTree<3, decltype(adaptor_of(std::declval<const Points&>()))>;

Points uniform_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points pts(n);
  for (auto& p : pts)
    for (double& x : p) x = u(rng);
  return pts;
}

Points blob_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  Points centres(8), pts(n);
  for (auto& c : centres)
    for (double& x : c) x = u(rng);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = i % 2 ? 0.01 : 0.1;
    for (int k = 0; k < 3; ++k) pts[i][k] = centres[i % centres.size()][k] + w * g(rng);
  }
  return pts;
}

Points cubic_lattice(int n) {
  Points pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) pts.push_back({double(i), double(j), double(k)});
  return pts;
}

/// Brute force: the smallest (angle, id) over every point not excluded.
std::optional<PivotHit> brute_first_met(const Points& pts, const PivotCircle& c,
                                        std::span<const std::uint32_t> exclude) {
  std::optional<PivotHit> best;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    if (std::find(exclude.begin(), exclude.end(), i) != exclude.end()) continue;
    const double v = angle_met(c, pts[i]);
    if (!(v < std::numeric_limits<double>::infinity())) continue;
    if (!best || v < best->angle) best = PivotHit{i, v};
  }
  return best;
}

void expect_same(const std::optional<PivotHit>& tree, const std::optional<PivotHit>& brute, int t) {
  ASSERT_EQ(tree.has_value(), brute.has_value()) << "query " << t;
  if (!tree) return;
  EXPECT_EQ(tree->id, brute->id) << "query " << t;
  EXPECT_EQ(tree->angle, brute->angle) << "query " << t;
}

/// MS1 about random edges of triangles of near points (ball radius above the circumradius) and MS3
/// about random axes, tree against brute force.
void check_searchers(const Points& pts, double r_scale, int queries, std::uint64_t seed) {
  const auto adaptor = adaptor_of(pts);
  const auto tree = PointTree::with_all(adaptor);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(pts.size() - 1));
  std::normal_distribution<double> g;
  int ms1 = 0;
  for (int t = 0; t < queries; ++t) {
    // A triangle of a point and two of its 7 nearest neighbours.
    const std::uint32_t a = pick(rng);
    const auto near = k_nearest<3>(tree, pts[a], 8);
    const std::uint32_t b = near[1 + rng() % 7].id, c = near[1 + rng() % 7].id;
    const double r = r_scale * (1.0 + std::abs(g(rng)));
    if (const auto pivot = pivot_about_edge(pts[a], pts[b], pts[c], r)) {
      const std::array<std::uint32_t, 3> exclude{a, b, c};
      expect_same(first_point_met(tree, *pivot, exclude), brute_first_met(pts, *pivot, exclude), t);
      ++ms1;
    }
    const Point3 axis{g(rng), g(rng), g(rng)};
    const Point3 start = add_scaled(pts[a], Point3{g(rng), g(rng), g(rng)}, r);
    if (const auto pivot = pivot_about_axis(pts[a], axis, start, r)) {
      const std::array<std::uint32_t, 1> exclude{a};
      expect_same(first_point_met(tree, *pivot, exclude), brute_first_met(pts, *pivot, exclude), t);
    }
  }
  EXPECT_GT(ms1, queries / 4);  // enough triangles had a ball of the radius
}

TEST(PivotSearches, Ms1Ms3EqualBruteForceOnUniformPoints) {
  check_searchers(uniform_points(20000, 1), 0.05, 400, 2);
}

TEST(PivotSearches, Ms1Ms3EqualBruteForceOnBlobs) {
  check_searchers(blob_points(20000, 3), 0.02, 400, 4);
}

TEST(PivotSearches, Ms1Ms3EqualBruteForceOnLatticeWithTies) {
  // Lattice triangles of neighbouring points and radii that put many points on the ball at
  // once: ties in angle, to the lower id. Random triangles too (any three lattice points).
  const Points pts = cubic_lattice(14);
  check_searchers(pts, 1.0, 300, 5);
  const auto adaptor = adaptor_of(pts);
  const auto tree = PointTree::with_all(adaptor);
  auto id = [](int i, int j, int k) { return static_cast<std::uint32_t>((i * 14 + j) * 14 + k); };
  int ties = 0;
  for (int i = 1; i < 12; i += 3)
    for (int j = 1; j < 12; j += 3)
      for (double r : {std::sqrt(0.5), std::sqrt(0.75), 1.0, 1.5}) {
        const std::array<std::uint32_t, 3> tri{id(i, j, 5), id(i + 1, j, 5), id(i, j + 1, 5)};
        const auto pivot = pivot_about_edge(pts[tri[0]], pts[tri[1]], pts[tri[2]], r);
        ASSERT_TRUE(pivot);
        const auto brute = brute_first_met(pts, *pivot, tri);
        expect_same(first_point_met(tree, *pivot, tri), brute, i * 100 + j);
        int at_same_angle = 0;
        for (std::uint32_t p = 0; p < pts.size(); ++p)
          at_same_angle += p != tri[0] && p != tri[1] && p != tri[2] &&
                           angle_met(*pivot, pts[p]) == brute->angle;
        ties += at_same_angle > 1;
      }
  EXPECT_GT(ties, 0);  // the lattice does produce ties
}

TEST(PivotSearches, Ms3AngleMatchesClosedForm) {
  // Ball of radius 1 centred at (1, 0, 0), turned about the z axis through the origin; a point
  // at distance d from the axis, azimuth γ, is met when |c(θ) − P| = 1:
  // 1 + d² − 2d cos(θ − γ) = 1 → θ = γ − acos(d/2).
  const auto pivot = pivot_about_axis({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1.0);
  ASSERT_TRUE(pivot);
  for (double d : {0.5, 1.0, 1.7}) {
    const double gamma = 2.0;
    const Points pts{{0, 0, 0}, {d * std::cos(gamma), d * std::sin(gamma), 0.0}, {5, 5, 5}};
    const auto adaptor = adaptor_of(pts);
    const auto tree = PointTree::with_all(adaptor);
    const std::array<std::uint32_t, 1> exclude{0};
    const auto hit = first_point_met(tree, *pivot, exclude);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 1u);
    EXPECT_NEAR(hit->angle, gamma - std::acos(d / 2.0), 1e-12);  // rounding only
  }
}

TEST(PivotSearches, Ms1PivotBallIsEmptyAndTouchesThreePoints) {
  // On a Delaunay-like start (a triangle of nearest neighbours with an empty ball), the ball
  // turned by the angle found touches A, B and P and holds no point: the next surface triangle.
  const Points pts = uniform_points(5000, 7);
  const auto adaptor = adaptor_of(pts);
  const auto tree = PointTree::with_all(adaptor);
  const double r = 0.045;
  int checked = 0;
  for (std::uint32_t a = 0; a < 1000; ++a) {
    const auto near = k_nearest<3>(tree, pts[a], 3);
    const std::array<std::uint32_t, 3> tri{a, near[1].id, near[2].id};
    const auto pivot = pivot_about_edge(pts[tri[0]], pts[tri[1]], pts[tri[2]], r);
    if (!pivot) continue;
    auto centre_at = [&](double angle) {
      return add_scaled(add_scaled(pivot->centre, pivot->x, pivot->radius * std::cos(angle)),
                        pivot->y, pivot->radius * std::sin(angle));
    };
    if (!within_radius<3>(tree, centre_at(0.0), r * (1 - 1e-9)).empty())
      continue;                                               // start not empty
    const std::array<std::uint32_t, 2> edge{tri[0], tri[1]};  // C is met again coming round
    const auto hit = first_point_met(tree, *pivot, edge);
    ASSERT_EQ(hit.has_value(), brute_first_met(pts, *pivot, edge).has_value());
    if (!hit) continue;  // at the edge of the cloud the ball turns through empty space
    const Point3 centre = centre_at(hit->angle);
    auto distance = [&](std::uint32_t i) {
      return std::sqrt(dot(sub(pts[i], centre), sub(pts[i], centre)));
    };
    EXPECT_NEAR(distance(tri[0]), r, 1e-12);
    EXPECT_NEAR(distance(tri[1]), r, 1e-12);
    EXPECT_NEAR(distance(hit->id), r, 1e-9);  // acos near a tangent: 1e-9 of r
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      ASSERT_GE(distance(i), r - 1e-9) << "point " << i;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(PivotSearches, NoneWhenNothingIsMetOrNoBallFits) {
  const Points pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {10, 10, 10}};
  const auto adaptor = adaptor_of(pts);
  const auto tree = PointTree::with_all(adaptor);
  // Ball radius 1 on the triangle: the far point is never met, the triangle's points excluded.
  const auto pivot = pivot_about_edge(pts[0], pts[1], pts[2], 1.0);
  ASSERT_TRUE(pivot);
  const std::array<std::uint32_t, 3> tri{0, 1, 2};
  EXPECT_FALSE(first_point_met(tree, *pivot, tri));
  EXPECT_FALSE(brute_first_met(pts, *pivot, tri));
  // Without excluding C, the ball comes round to C from the other side: 2π − 2·(angle of C).
  const std::array<std::uint32_t, 2> edge{0, 1};
  const auto back = first_point_met(tree, *pivot, edge);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->id, 2u);
  EXPECT_GT(back->angle, std::numbers::pi);
  // No ball: radius below the circumradius √2/2, collinear points, the centre on the axis.
  EXPECT_FALSE(pivot_about_edge(pts[0], pts[1], pts[2], 0.7));
  EXPECT_FALSE(pivot_about_edge(pts[0], pts[1], {2, 0, 0}, 5.0));
  EXPECT_FALSE(pivot_about_axis({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 1.0));
  EXPECT_FALSE(pivot_about_axis({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, 1.0));
  // An empty tree.
  const Points none;
  const auto empty_adaptor = adaptor_of(none);
  const auto empty = PointTree::with_all(empty_adaptor);
  EXPECT_FALSE(first_point_met(empty, *pivot));
}

TEST(PivotSearches, Cs1FindsSegmentsLikeBruteForce) {
  // Segments among 400 random points (some repeated, some reversed), half of them removed from
  // the tree: CS1 equals a scan of the held segments for every queried pair.
  const Points pts = uniform_points(400, 9);
  std::mt19937_64 rng(10);
  std::uniform_int_distribution<std::uint32_t> pick(0, 399);
  std::vector<std::array<std::uint32_t, 2>> ends;
  for (int s = 0; s < 3000; ++s) {
    const std::uint32_t a = pick(rng);
    std::uint32_t b = pick(rng);
    if (b == a) b = (a + 1) % 400;
    ends.push_back({a, b});
    if (s % 10 == 0) ends.push_back({b, a});
  }
  const SegmentsAdaptor<3> segments{&pts, &ends};
  auto tree = SpaceTree<3, SegmentsAdaptor<3>>::with_all(segments);
  for (std::uint32_t s = 0; s < ends.size(); s += 2) tree.remove(s);
  ASSERT_EQ(tree.check(), "");
  int found = 0;
  for (int t = 0; t < 4000; ++t) {
    const std::uint32_t p1 = t < 2000 ? ends[t][0] : pick(rng),
                        p2 = t < 2000 ? ends[t][1] : pick(rng);
    std::optional<std::uint32_t> brute;
    for (std::uint32_t s = 0; s < ends.size() && !brute; ++s)
      if (tree.contains(s) &&
          ((ends[s][0] == p1 && ends[s][1] == p2) || (ends[s][0] == p2 && ends[s][1] == p1)))
        brute = s;
    ASSERT_EQ(find_segment<3>(tree, p1, p2), brute) << "pair " << p1 << " " << p2;
    found += brute.has_value();
  }
  EXPECT_GT(found, 500);
  EXPECT_FALSE(find_segment<3>(tree, 5, 5));  // no segment from a point to itself
}

}  // namespace
}  // namespace shockfield::geometry
