// The pivoting rolling ball (Xu et al. 2015 steps I–III on MS1/MS3/CS1) against the surface built
// from the Delaunay division for the same points and radius: both are the set of triangles a ball
// of radius r rolled from outside touches, so they must agree — the same triangles in general
// position (random points on a sphere), hence area and volume within 1% (here: to rounding), a
// closed edge-manifold surface with χ = 2 — and both within 1% of the sphere's 4π and 4π/3 at
// 20 000 points (inscribed polyhedron deficit O(h²), h ~ 0.025). Bad radii are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/pivoting_ball.hpp"
#include "unit/geometry/sampled_shapes.hpp"

namespace shockfield::geometry {
namespace {

std::vector<Point3> sphere_points(std::size_t n, double r, std::uint64_t seed) {
  return testing::sphere(n, r, {0, 0, 0}, seed);
}

/// The triangles as sorted vertex triples, each rotated to start at its smallest vertex (the
/// orientation is kept).
std::vector<std::array<std::int32_t, 3>> canonical(const TriangleSurface& s) {
  auto t = s.triangles;
  for (auto& f : t) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(t.begin(), t.end());
  return t;
}

TEST(PivotingBall, SphereEqualsTheDelaunaySurface) {
  const auto points = sphere_points(20000, 1.0, 1);
  const double r = 0.1;
  const auto pivot = pivoting_ball_surface(points, r);
  const auto delaunay = rolling_ball_surface(delaunay_division<3>(points), r);
  EXPECT_TRUE(pivot.manifold);
  EXPECT_EQ(pivot.euler_characteristic, 2);
  EXPECT_EQ(canonical(pivot), canonical(delaunay));  // same triangles, same orientation
  EXPECT_NEAR(pivot.area, delaunay.area, 0.01 * delaunay.area);
  EXPECT_NEAR(pivot.volume, delaunay.volume, 0.01 * delaunay.volume);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(pivot.area, 4 * pi, 0.01 * 4 * pi);
  EXPECT_NEAR(pivot.volume, 4 * pi / 3, 0.01 * 4 * pi / 3);
  // Copies of 500 points appended: the copies are left out, the surface is the same.
  auto with_copies = points;
  for (std::size_t i = 0; i < 500; ++i) with_copies.push_back(points[37 * i]);
  EXPECT_EQ(canonical(pivoting_ball_surface(with_copies, r)), canonical(pivot));
}

TEST(PivotingBall, TorusEqualsTheDelaunaySurfaceWithEulerCharacteristicZero) {
  // 10 000 points uniform in area on a torus R = 1, a = 0.4, ball 0.2: the hole stays open.
  const auto points = testing::torus(10000, 1.0, 0.4, 2);
  const auto pivot = pivoting_ball_surface(points, 0.2);
  EXPECT_TRUE(pivot.manifold);
  EXPECT_EQ(pivot.euler_characteristic, 0);
  EXPECT_EQ(canonical(pivot), canonical(rolling_ball_surface(delaunay_division<3>(points), 0.2)));
}

TEST(PivotingBall, FollowsOnlyTheComponentOfItsSeed) {
  // Two unit spheres 3 apart (documented limit): the Delaunay surface has both (χ = 4), the
  // pivot the one on the point of largest x (χ = 2, half the volume).
  auto points = sphere_points(3000, 1.0, 3);
  for (auto p : sphere_points(3000, 1.0, 4)) points.push_back({p[0] + 3.0, p[1], p[2]});
  const auto pivot = pivoting_ball_surface(points, 0.3);
  const auto delaunay = rolling_ball_surface(delaunay_division<3>(points), 0.3);
  EXPECT_EQ(delaunay.euler_characteristic, 4);
  EXPECT_EQ(pivot.euler_characteristic, 2);
  EXPECT_NEAR(pivot.volume, 0.5 * delaunay.volume, 0.01 * delaunay.volume);
}

TEST(PivotingBall, LatticeBlockWithCosphericalTiesIsItsBox) {
  // A 6×6×6 simple cubic block: every face square is four cocircular points (exact ties, broken
  // by the 1e-9 move of the points). A ball of radius 3 rolls over the box: area 6·5², volume 5³,
  // χ = 2, as the Delaunay surface.
  std::vector<Point3> points;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) points.push_back({double(i), double(j), double(k)});
  const auto pivot = pivoting_ball_surface(points, 3.0);
  const auto delaunay = rolling_ball_surface(delaunay_division<3>(points), 3.0);
  EXPECT_TRUE(pivot.manifold);
  EXPECT_EQ(pivot.euler_characteristic, 2);
  EXPECT_NEAR(pivot.area, 150.0, 1e-9);  // rounding only: the triangles are the box's
  EXPECT_NEAR(pivot.volume, 125.0, 1e-9);
  EXPECT_NEAR(delaunay.area, 150.0, 1e-9);
  EXPECT_EQ(pivot.triangles.size(), delaunay.triangles.size());
}

TEST(PivotingBall, RefusesRadiiThatCannotCloseAndTooFewPoints) {
  const auto points = sphere_points(2000, 1.0, 2);
  // Far below the spacing (~0.08): the seed ball meets too few points.
  EXPECT_THROW(pivoting_ball_surface(points, 0.01), InputError);
  // About the spacing: the ball falls through the sampling into the sphere (the Delaunay
  // surface is not manifold there); the pivot makes triangles twice and says so.
  EXPECT_FALSE(rolling_ball_surface(delaunay_division<3>(points), 0.08).manifold);
  try {
    pivoting_ball_surface(points, 0.08);
    ADD_FAILURE() << "no error for an open surface";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the surface does not close"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(pivoting_ball_surface(points, -1.0), InputError);
  EXPECT_THROW(pivoting_ball_surface({{0, 0, 0}, {1, 0, 0}}, 1.0), InputError);
  EXPECT_THROW(pivoting_ball_surface({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}, 1.0), InputError);
  std::vector<Point3> bad = points;
  bad[7][1] = std::nan("");
  EXPECT_THROW(pivoting_ball_surface(bad, 0.3), InputError);
}

}  // namespace
}  // namespace shockfield::geometry
