// Analytic values for digitised shapes: Euler characteristic of disks, annuli, several disks,
// a ball, a hollow sphere and a torus (exact, all connectivities and boundaries), and area,
// boundary length, surface area and mean breadth converging to the continuum values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shapes.hpp"
#include "shockfield/analysis/minkowski.hpp"

namespace sa = shockfield::analysis;
using sa::testing::ball;
using sa::testing::digitise;
using sa::testing::disk;
constexpr double pi = std::numbers::pi;

namespace {

const std::vector<double> kHalf{0.5};

std::vector<sa::MinkowskiOptions> all_options() {
  std::vector<sa::MinkowskiOptions> out;
  for (auto b : {sa::Boundary::open, sa::Boundary::periodic})
    for (auto c : {sa::Connectivity2D::four, sa::Connectivity2D::eight})
      for (auto a : {sa::Adjacency3D::six_26, sa::Adjacency3D::twentysix_6}) out.push_back({b, c, a});
  return out;
}

long chi(const sa::GridField& f, const sa::MinkowskiOptions& o) {
  return f.dimension() == 2 ? long(sa::minkowski_2d(f, kHalf, o)[0].euler)
                            : long(sa::minkowski_3d(f, kHalf, o)[0].euler);
}

}  // namespace

TEST(MinkowskiShapes, DiskAnnulusAndSeveralDisks2D) {
  const auto annulus = digitise(64, 64, 1, [](double x, double y, double) {
    const double r = std::hypot(x - 31.3, y - 32.6);
    return r >= 9.0 && r <= 20.0;
  });
  for (int k = 1; k <= 5; ++k) {
    const auto disks = digitise(96, 20, 1, [k](double x, double y, double) {
      for (int i = 0; i < k; ++i)
        if (std::hypot(x - (9.4 + 18.0 * i), y - 9.7) <= 6.5) return true;
      return false;
    });
    for (const auto& o : all_options()) EXPECT_EQ(chi(disks, o), k);
  }
  for (const auto& o : all_options()) {
    EXPECT_EQ(chi(disk(64, 20.0, 31.3, 32.6), o), 1);
    EXPECT_EQ(chi(annulus, o), 0);
  }
}

TEST(MinkowskiShapes, BlackDropInWhiteIsMinusOneOnlyWhenTheSurroundingDoesNotCount) {
  // Xu et al. (2015) §3.1: "χ = −1 in the case with only black drop in a large white lattice".
  auto drop = disk(48, 10.0, 23.6, 24.2);
  for (auto& v : drop.values) v = 1.0 - v;
  sa::MinkowskiOptions o;
  o.boundary = sa::Boundary::periodic;
  EXPECT_EQ(chi(drop, o), -1);
  o.boundary = sa::Boundary::open;  // the white frame is one domain with one hole
  EXPECT_EQ(chi(drop, o), 0);
}

TEST(MinkowskiShapes, BallHollowSphereTorus3D) {
  const auto hollow = digitise(40, 40, 40, [](double x, double y, double z) {
    const double r = std::sqrt((x - 19.6) * (x - 19.6) + (y - 19.2) * (y - 19.2) +
                               (z - 19.9) * (z - 19.9));
    return r >= 8.0 && r <= 15.0;
  });
  const auto torus = digitise(48, 48, 24, [](double x, double y, double z) {
    const double rho = std::hypot(x - 23.7, y - 24.1) - 14.0;
    return std::hypot(rho, z - 11.6) <= 5.5;
  });
  for (const auto& o : all_options()) {
    EXPECT_EQ(chi(ball(36, 12.0, 17.4), o), 1);
    EXPECT_EQ(chi(hollow, o), 2);
    EXPECT_EQ(chi(torus, o), 0);
  }
}

// Area and Crofton boundary length of digitised disks. Each lattice line crosses a digitised
// convex set twice, and the number of lines hitting it is its digitised width (2r ± 1), so the
// relative length error is bounded by about 1/r (stated estimator error, docs/analysis-minkowski.md).
TEST(MinkowskiShapes, DiskAreaAndBoundaryLengthConverge) {
  double previous = 1.0;
  for (double r : {8.0, 16.0, 32.0, 64.0, 128.0}) {
    const std::size_t n = std::size_t(2 * r + 8);
    const auto f = disk(n, r, 0.5 * n - 0.37, 0.5 * n + 0.21);
    sa::MinkowskiOptions o;
    o.boundary = sa::Boundary::open;
    const auto m = sa::minkowski_2d(f, kHalf, o)[0];
    const double area = m.area_fraction * double(n * n);
    const double length_error = std::abs(m.boundary_length / (2 * pi * r) - 1.0);
    EXPECT_NEAR(area / (pi * r * r), 1.0, 1.0 / r) << "r = " << r;
    EXPECT_LT(length_error, 1.0 / r) << "r = " << r;
    previous = std::min(previous, length_error);
    RecordProperty("disk_r" + std::to_string(int(r)) + "_length_error", std::to_string(length_error));
  }
  EXPECT_LT(previous, 0.005);
}

// Ball: 13-direction Crofton surface area → 4πr², mean breadth → 2r, errors O(1/r).
TEST(MinkowskiShapes, BallSurfaceAndMeanBreadthConverge) {
  for (double r : {6.0, 12.0, 24.0}) {
    const std::size_t n = std::size_t(2 * r + 6);
    const auto f = ball(n, r, 0.5 * n - 0.41);
    for (auto a : {sa::Adjacency3D::six_26, sa::Adjacency3D::twentysix_6}) {
      sa::MinkowskiOptions o;
      o.boundary = sa::Boundary::open;
      o.adjacency3d = a;
      const auto m = sa::minkowski_3d(f, kHalf, o)[0];
      const double volume = m.volume_fraction * double(n * n * n);
      EXPECT_NEAR(volume / (4.0 / 3.0 * pi * r * r * r), 1.0, 1.0 / r) << "r = " << r;
      EXPECT_NEAR(m.surface_area / (4 * pi * r * r), 1.0, 1.0 / r) << "r = " << r;
      EXPECT_NEAR(m.mean_breadth / (2 * r), 1.0, 1.0 / r) << "r = " << r;
      EXPECT_NEAR(m.integral_mean_curvature, 2 * pi * m.mean_breadth, 1e-12);
      std::printf("ball r=%g adj=%d  V %.5f  S %.5f  b %.5f\n", r, int(a),
                  volume / (4.0 / 3.0 * pi * r * r * r), m.surface_area / (4 * pi * r * r),
                  m.mean_breadth / (2 * r));
    }
  }
}

TEST(MinkowskiShapes, UniformFieldAndSpacing) {
  const auto white = sa::GridField::filled(10, 12, 1, 1.0);
  sa::MinkowskiOptions o;
  const auto p = sa::minkowski_2d(white, kHalf, o)[0];  // periodic: a torus
  EXPECT_EQ(p.area_fraction, 1.0);
  EXPECT_EQ(p.boundary_length, 0.0);
  EXPECT_EQ(p.euler, 0);
  EXPECT_TRUE(std::isnan(p.euler_per_black_node));
  o.boundary = sa::Boundary::open;
  auto f = disk(40, 12.0, 19.3, 20.1);
  const auto unit = sa::minkowski_2d(f, kHalf, o)[0];
  f.spacing = {0.5, 0.5, 1.0};
  const auto half = sa::minkowski_2d(f, kHalf, o)[0];
  EXPECT_DOUBLE_EQ(half.boundary_length, 0.5 * unit.boundary_length);
  EXPECT_EQ(half.euler, unit.euler);
  EXPECT_DOUBLE_EQ(unit.euler_per_black_node, 1.0 / double(40 * 40 - unit.white_cells));  // eq. 33
}
