// The shape measures of series.csv on domains of known shape: a disc, a sphere, an ellipsoid
// across a periodic face and a 1D slab. The interfaces are diffuse (tanh of logistic length
// l = √(2D) = 1.41): the tolerances allow the O((l/R)²) widening of the moments and the Crofton
// estimators' few-percent digitisation error at R ≈ 10 cells (analysis/minkowski's own tests).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/phasefield/domain_measures.hpp"
#include "shockfield/phasefield/initial.hpp"

namespace shockfield::phasefield {
namespace {

const Model kModel{0.5, 1.0};
constexpr double kPi = std::numbers::pi;

TEST(PhasefieldDomainMeasures, DiscPerimeterCurvatureAndAxes) {
  const Grid g{2, {96, 96, 1}, 0.5};
  const double R = 12.0;
  const auto xi = initial_field(g, kModel, {{Domain::Kind::sphere, {24.0, 20.0, 0.0}, {R, R, R}}});
  const DomainMeasures m = domain_measures(g, xi);
  EXPECT_NEAR(m.surface, 2 * kPi * R, 0.02 * 2 * kPi * R);
  EXPECT_EQ(m.euler, 1);
  EXPECT_NEAR(m.mean_curvature, 1.0 / R, 0.02 / R);
  EXPECT_NEAR(m.semi_axes[0], R, 0.02 * R);
  EXPECT_NEAR(m.semi_axes[1], R, 0.02 * R);
  EXPECT_EQ(m.semi_axes[2], 0.0);
  EXPECT_NEAR(m.center[0], 24.0, 1e-6);
  EXPECT_NEAR(m.center[1], 20.0, 1e-6);
}

TEST(PhasefieldDomainMeasures, SphereAreaAndMeanCurvature) {
  const Grid g{3, {48, 48, 48}, 0.5};
  const double R = 8.0;
  const auto xi = initial_field(g, kModel, {{Domain::Kind::sphere, {12.0, 12.0, 12.0}, {R, R, R}}});
  const DomainMeasures m = domain_measures(g, xi);
  EXPECT_NEAR(m.surface, 4 * kPi * R * R, 0.03 * 4 * kPi * R * R);
  EXPECT_EQ(m.euler, 1);
  EXPECT_NEAR(m.mean_curvature, 1.0 / R, 0.03 / R);  // M/S = 4πR / 4πR²
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m.semi_axes[a], R, 0.03 * R) << a;
}

// An ellipsoid whose centre is 1 from the x = 0 face of a periodic box: the circular mean finds
// the centre and the minimum image keeps it whole; the long axis is x.
TEST(PhasefieldDomainMeasures, EllipsoidAcrossAPeriodicFace) {
  const Grid g{3, {64, 48, 40}, 0.5};
  const auto xi = initial_field(g, kModel, {{Domain::Kind::ellipsoid, {1.0, 12.0, 10.0}, {12.0, 8.0, 6.0}}});
  const DomainMeasures m = domain_measures(g, xi);
  EXPECT_NEAR(m.semi_axes[0], 12.0, 0.3);
  EXPECT_NEAR(m.semi_axes[1], 8.0, 0.3);
  EXPECT_NEAR(m.semi_axes[2], 6.0, 0.3);
  EXPECT_NEAR(m.long_axis[0], 1.0, 1e-6);
  EXPECT_NEAR(m.center[0], 1.0, 1e-6);
  EXPECT_NEAR(m.center[1], 12.0, 1e-6);
  EXPECT_EQ(m.euler, 1);
}

TEST(PhasefieldDomainMeasures, SlabIn1DHasTwoFronts) {
  const Grid g{1, {200, 1, 1}, 0.5};
  const auto xi = initial_field(g, kModel, {{Domain::Kind::slab, {50.0, 0, 0}, {15.0, 0, 0}, {1, 0, 0}}});
  const DomainMeasures m = domain_measures(g, xi);
  EXPECT_EQ(m.surface, 2.0);
  EXPECT_EQ(m.euler, 1);
  // A segment of half length h has moment h²/3. Its nodes with ξ > 1/2 are the 59 nodes 35.5 …
  // 64.5; N evenly spaced nodes have variance (N² − 1)dx²/12, so √(3λ) = dx √(N² − 1)/2 = 14.748.
  EXPECT_NEAR(m.semi_axes[0], 0.5 * std::sqrt(59.0 * 59.0 - 1.0) / 2.0, 1e-9);
  EXPECT_NEAR(m.center[0], 50.0, 1e-6);
}

}  // namespace
}  // namespace shockfield::phasefield
