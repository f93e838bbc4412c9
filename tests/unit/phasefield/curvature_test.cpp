// The curvature law of the well-posed model (docs/theory/phasefield.md): an hcp disc (sphere)
// moves at Ṙ = c₀ − (n − 1)D/R, so at a = 1/2 R² = R₀² − 2(n − 1)Dt, and for a < 1/2 the critical
// radius R* = D/c₀ separates shrinking from growing discs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/phasefield/initial.hpp"
#include "shockfield/phasefield/solver.hpp"

namespace shockfield::phasefield {
namespace {

// The disc radius from the hcp area Σ ξ dA = πR² (the tanh profile's correction to the area is
// O(l²), l = √(2D), and is taken out by measuring R₀ the same way).
double disc_radius(const Solver& s) { return std::sqrt(s.measures().integral / std::numbers::pi); }

Solver& disc(Solver& s, const Model& m, double R) {
  const double c = 0.5 * s.grid().length(0);
  s.field() = initial_field(s.grid(), m, {Domain{Domain::Kind::sphere, {c, c, 0}, {R, R, R}}});
  return s;
}

// D = 1, dx = l/4 (l = √(2D)), R₀ = 25 ≈ 17.7 l on a periodic 64 × 64 box, explicit at 0.8 of the
// limit; R(t) against √(R₀² − 2Dt) within 1 % until R = 0.6 R₀ (15 ≈ 10.6 l). The deviation is the
// O((l/R)²) correction to the sharp-interface law, not discretisation (halving dx or switching to
// the spectral scheme leaves it): measured 0.4 % at R = 0.6 R₀ here, growing to 0.9 % at R = R₀/2
// (0.375 % there for D = 1/2), so the window stops at 0.6 R₀.
TEST(PhasefieldCurvature, DiscAtEqualWellsShrinksAsRSquaredLinear) {
  const Model m{0.5, 1.0};
  const Grid g{2, {182, 182, 1}, std::sqrt(2.0) / 4};
  Solver s(g, m, Scheme::explicit_euler, 0.8 * explicit_step_limit(g, m));
  disc(s, m, 25.0);
  const double R0 = disc_radius(s);
  const double t_end = (R0 * R0 - 0.36 * R0 * R0) / (2 * m.D);
  double worst = 0;
  while (s.time() < t_end) {
    for (int k = 0; k < 200; ++k) s.step();
    const double R = disc_radius(s), exact = std::sqrt(R0 * R0 - 2 * m.D * s.time());
    worst = std::max(worst, std::abs(R / exact - 1));
  }
  EXPECT_LT(worst, 0.01);
  RecordProperty("max_relative_radius_error", std::to_string(worst));
}

// 3D, spectral: a sphere at a = 1/2 follows R² = R₀² − 4Dt. D = 1/2 (l = 1), dx = l/2 (the
// spectral Laplacian resolves the tanh profile: its spectrum at the Nyquist mode is ~e^{−2π²}),
// R₀ = 8 l on a periodic 24 l box, dt = 0.05, until R = 0.75 R₀; R from Σ ξ dV = 4πR³/3 (the profile's
// share of the volume is O(l²R), not cancelled as in 2D: part of the measured 0.35 %; with dt
// halved 0.33 %). Tolerance 1 % (the issue's).
TEST(PhasefieldCurvature, SphereAtEqualWellsShrinksAsRSquaredLinear) {
  const Model m{0.5, 0.5};
  const Grid g{3, {48, 48, 48}, 0.5};
  Solver s(g, m, Scheme::spectral, 0.05);
  const double c = 0.5 * g.length(0);
  s.field() = initial_field(g, m, {Domain{Domain::Kind::sphere, {c, c, c}, {8.0, 8.0, 8.0}}});
  const auto radius = [&] { return std::cbrt(s.measures().integral / (4.0 / 3.0 * std::numbers::pi)); };
  const double R0 = radius(), t_end = (1 - 0.75 * 0.75) * R0 * R0 / (4 * m.D);
  double worst = 0;
  while (s.time() < t_end) {
    for (int k = 0; k < 20; ++k) s.step();
    worst = std::max(worst, std::abs(radius() / std::sqrt(R0 * R0 - 4 * m.D * s.time()) - 1));
  }
  EXPECT_LT(worst, 0.01);
  RecordProperty("max_relative_radius_error", std::to_string(worst));
}

// a = 0.4, D = 1: c₀ = √0.5·0.2, R* = D/c₀ ≈ 7.07 (l = 1.41, dx = 0.25). A disc of 1.25 R* grows,
// one of 0.8 R* shrinks (both by more than 5 % of R₀ in the run, so the sign is not noise).
TEST(PhasefieldCurvature, CriticalRadiusSeparatesGrowthFromShrinkage) {
  const Model m{0.4, 1.0};
  const double Rc = m.critical_radius(2);
  ASSERT_NEAR(Rc, 1.0 / (std::sqrt(0.5) * 0.2), 1e-12);
  const Grid g{2, {128, 128, 1}, 0.25};
  for (const double ratio : {0.8, 1.25}) {
    Solver s(g, m, Scheme::explicit_euler, 0.8 * explicit_step_limit(g, m));
    disc(s, m, ratio * Rc);
    const double R0 = disc_radius(s);
    for (int k = 0; k < 3000; ++k) s.step();
    const double change = disc_radius(s) / R0 - 1;
    if (ratio > 1)
      EXPECT_GT(change, 0.05) << "R0/R* " << ratio;
    else
      EXPECT_LT(change, -0.05) << "R0/R* " << ratio;
  }
}

// a = 0.45 (c₀ = √(D/2)·0.1, R* = D/c₀ = 7.07 for D = 1/4): a disc of R₀ = 10 grows along the
// integrated law t(R) = [R − R₀ + R* ln((R − R*)/(R₀ − R*))]/c₀ (docs/theory/phasefield.md). R is
// the ξ = 1/2 level, R² = R_eq² − π²l²/3 (the tanh profile's share of Σ ξ dA). Spectral, l/dx = 2,
// dt = 0.05, t = 120 (R grows to ≈ 11.5); |t_law(R) − t| within 0.5 % of the run time (the example
// examples/phasefield_domain, at l/dx = 5.7, measures 0.07 %).
TEST(PhasefieldCurvature, GrowingDiscFollowsIntegratedCurvatureLaw) {
  const Model m{0.45, 0.25};
  const double l = m.front_length(), c0 = m.front_speed(), Rc = m.critical_radius(2);
  const Grid g{2, {113, 113, 1}, l / 2};
  Solver s(g, m, Scheme::spectral, 0.05);
  disc(s, m, 10.0);
  const auto level_radius = [&] {
    const double R = disc_radius(s);
    return std::sqrt(R * R - std::numbers::pi * std::numbers::pi * l * l / 3);
  };
  const double R0 = level_radius(), t_end = 120.0;
  double worst = 0;
  while (s.time() < t_end - 1e-9) {
    for (int k = 0; k < 100; ++k) s.step();
    const double R = level_radius();
    const double t_law = (R - R0 + Rc * std::log((R - Rc) / (R0 - Rc))) / c0;
    worst = std::max(worst, std::abs(t_law - s.time()) / t_end);
  }
  EXPECT_GT(level_radius(), R0 + 1.0);  // it grew
  EXPECT_LT(worst, 5e-3);
  RecordProperty("max_time_error_over_run_time", std::to_string(worst));
}

}  // namespace
}  // namespace shockfield::phasefield
