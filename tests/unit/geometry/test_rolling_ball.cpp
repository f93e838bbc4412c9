// Rolling-ball surfaces of sampled shapes: closed, consistently oriented, edge-manifold, with the
// Euler characteristic of the shape and area and volume within 1% of the exact values. Sampling:
// points uniform in area (a sphere: 20 000 points; a torus R = 1, a = 0.4: 30 000), so the
// inscribed polyhedron's deficit, O(h²) with spacing h ~ 0.02, stays well under 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/rolling_ball.hpp"

namespace shockfield::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::array<double, 3>> sphere(std::size_t n, double r, std::array<double, 3> c,
                                          std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<std::array<double, 3>> p(n);
  for (auto& x : p) {
    const double a = g(rng), b = g(rng), z = g(rng), s = r / std::sqrt(a * a + b * b + z * z);
    x = {c[0] + a * s, c[1] + b * s, c[2] + z * s};
  }
  return p;
}

// Uniform in area on the torus: accept the tube angle with probability (R + a cos v)/(R + a).
std::vector<std::array<double, 3>> torus(std::size_t n, double R, double a, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * kPi), w(0, 1);
  std::vector<std::array<double, 3>> p;
  while (p.size() < n) {
    const double t = u(rng), v = u(rng);
    if (w(rng) > (R + a * std::cos(v)) / (R + a)) continue;
    p.push_back({(R + a * std::cos(v)) * std::cos(t), (R + a * std::cos(v)) * std::sin(t), a * std::sin(v)});
  }
  return p;
}

TEST(RollingBall, SphereIsAClosedSphere) {
  const auto s = rolling_ball_surface(delaunay_division<3>(sphere(20000, 1.0, {0, 0, 0}, 1)), 0.3);
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_NEAR(s.area, 4 * kPi, 0.01 * 4 * kPi);
  EXPECT_NEAR(s.volume, 4 * kPi / 3, 0.01 * 4 * kPi / 3);
}

TEST(RollingBall, TorusHasEulerCharacteristicZero) {
  const double R = 1.0, a = 0.4;
  const auto s = rolling_ball_surface(delaunay_division<3>(torus(30000, R, a, 2)), 0.2);
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.euler_characteristic, 0);
  EXPECT_NEAR(s.area, 4 * kPi * kPi * R * a, 0.01 * 4 * kPi * kPi * R * a);
  EXPECT_NEAR(s.volume, 2 * kPi * kPi * R * a * a, 0.01 * 2 * kPi * kPi * R * a * a);
}

// Two unit spheres 0.6 apart: a ball of diameter 0.3 goes between them (two surfaces, χ = 4); a
// ball of radius 2 bridges the gap (one surface, χ = 2).
TEST(RollingBall, TwoSpheresSeparateOrMergeWithTheBallRadius) {
  auto p = sphere(10000, 1.0, {-1.3, 0, 0}, 3);
  const auto q = sphere(10000, 1.0, {1.3, 0, 0}, 4);
  p.insert(p.end(), q.begin(), q.end());
  const auto d = delaunay_division<3>(p);
  const auto apart = rolling_ball_surface(d, 0.15);
  EXPECT_TRUE(apart.manifold);
  EXPECT_EQ(apart.euler_characteristic, 4);
  EXPECT_NEAR(apart.volume, 2 * 4 * kPi / 3, 0.01 * 2 * 4 * kPi / 3);
  const auto merged = rolling_ball_surface(d, 2.0);
  EXPECT_TRUE(merged.manifold);
  EXPECT_EQ(merged.euler_characteristic, 2);
  EXPECT_GT(merged.volume, apart.volume);
}

TEST(RollingBall, RadiusTooSmallOrInvalidIsRejected) {
  const auto d = delaunay_division<3>(sphere(2000, 1.0, {0, 0, 0}, 5));
  EXPECT_THROW(rolling_ball_surface(d, 0.0), InputError);
  EXPECT_THROW(rolling_ball_surface(d, std::nan("")), InputError);
  try {
    rolling_ball_surface(d, 1e-4);
    ADD_FAILURE() << "a ball far smaller than the spacing gave a surface";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("passes between the points everywhere"), std::string::npos);
  }
}

}  // namespace
}  // namespace shockfield::geometry
