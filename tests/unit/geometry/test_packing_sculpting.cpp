// The packing-sculpting surface (Xu et al. 2015 §3.2.3): the convex hull sculpted to depth s.
// Sampled shapes give closed, consistently oriented, edge-manifold surfaces with the Euler
// characteristic the depth decides and area and volume within 1% of the exact values (sphere:
// 20 000 points, torus R = 1, a = 0.4: 30 000 — spacing h ~ 0.02, so the inscribed polyhedron's
// O(h²) deficit stays well under 1%). Without sculpting (a depth above every circumradius) the
// surface is the convex hull, whose volume is the whole division's. The torus at depth 0.2 gives the
// rolling-ball surface's figures for a ball of radius 0.2 (area 15.788, volume 3.1557).
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/rolling_ball.hpp"
#include "unit/geometry/sampled_shapes.hpp"

namespace shockfield::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_closed_manifold(const TriangleSurface& s, std::int64_t euler_characteristic) {
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.euler_characteristic, euler_characteristic);
}

TEST(PackingSculpting, SphereStaysItsConvexHull) {
  const auto d = delaunay_division<3>(testing::sphere(20000, 1.0, {0, 0, 0}, 1));
  const auto s = packing_sculpting_surface(d, 0.3);
  expect_closed_manifold(s, 2);
  EXPECT_NEAR(s.area, 4 * kPi, 0.01 * 4 * kPi);
  EXPECT_NEAR(s.volume, 4 * kPi / 3, 0.01 * 4 * kPi / 3);
  EXPECT_NEAR(s.volume, total_volume<3>(d), 1e-9 * s.volume);  // nothing sculpted: the hull
}

TEST(PackingSculpting, TorusIsSculptedThroughItsHole) {
  const double R = 1.0, a = 0.4;
  const auto d = delaunay_division<3>(testing::torus(30000, R, a, 2));
  // A depth of 100 leaves the convex hull but for a few flat tetrahedra on the flat caps over the
  // hole (nearly coplanar points, circumradius above 100): measured 2.7e-5 of the volume.
  const auto hull = packing_sculpting_surface(d, 100.0);
  expect_closed_manifold(hull, 2);
  EXPECT_NEAR(hull.volume, total_volume<3>(d), 1e-4 * hull.volume);
  const auto s = packing_sculpting_surface(d, 0.2);
  expect_closed_manifold(s, 0);
  EXPECT_NEAR(s.area, 4 * kPi * kPi * R * a, 0.01 * 4 * kPi * kPi * R * a);
  EXPECT_NEAR(s.volume, 2 * kPi * kPi * R * a * a, 0.01 * 2 * kPi * kPi * R * a * a);
}

// Two unit spheres 0.6 apart: a depth of 0.15 sculpts the gap open (two surfaces, χ = 4); a depth
// of 2 leaves the bridge over the gap (one surface, χ = 2).
TEST(PackingSculpting, TwoSpheresSeparateOrMergeWithTheDepth) {
  const auto d = delaunay_division<3>(testing::two_spheres(10000, 0.6));
  const auto apart = packing_sculpting_surface(d, 0.15);
  expect_closed_manifold(apart, 4);
  EXPECT_NEAR(apart.volume, 2 * 4 * kPi / 3, 0.01 * 2 * 4 * kPi / 3);
  EXPECT_NEAR(apart.area, 2 * 4 * kPi, 0.01 * 2 * 4 * kPi);
  const auto merged = packing_sculpting_surface(d, 2.0);
  expect_closed_manifold(merged, 2);
  EXPECT_GT(merged.volume, apart.volume);
}

// Two unit spheres touching at a point (10 000 points each, spacing about 0.035): a depth of 0.15
// cannot open the contact, so one surface with a neck, χ = 2, its volume a little above the two
// balls' (measured +1.0%: the neck). A depth of 0.05, about the spacing, carves into the spheres
// between their points in places and leaves a non-manifold remnant: refused.
TEST(PackingSculpting, TouchingSpheresMergeThroughANeck) {
  const auto d = delaunay_division<3>(testing::two_spheres(10000, 0.0));
  const auto s = packing_sculpting_surface(d, 0.15);
  expect_closed_manifold(s, 2);
  EXPECT_GT(s.volume, 2 * 4 * kPi / 3 * 0.99);
  EXPECT_LT(s.volume, 2 * 4 * kPi / 3 * 1.02);
  try {
    packing_sculpting_surface(d, 0.05);
    ADD_FAILURE() << "a depth about the spacing gave a non-manifold surface";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a manifold"), std::string::npos) << e.what();
  }
}

TEST(PackingSculpting, DepthThatCannotCloseIsRefused) {
  const auto d = delaunay_division<3>(testing::sphere(2000, 1.0, {0, 0, 0}, 5));
  EXPECT_THROW(packing_sculpting_surface(d, 0.0), InputError);
  EXPECT_THROW(packing_sculpting_surface(d, std::nan("")), InputError);
  try {
    packing_sculpting_surface(d, 1e-4);
    ADD_FAILURE() << "a depth far below the spacing gave a surface";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("removes every tetrahedron"), std::string::npos) << e.what();
  }

}

}  // namespace
}  // namespace shockfield::geometry
