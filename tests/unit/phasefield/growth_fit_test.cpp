// The growth-law fit of bridge domain-growth (phasefield/growth_fit.hpp): dR/dt = c₀ − (n − 1)D/R.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/phasefield/growth_fit.hpp"

namespace shockfield::phasefield {
namespace {

std::vector<double> times(int n, double step) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(step * i);
  return t;
}

// The closed form of the law (docs/theory/phasefield.md): t = [R − R₀ + R* ln((R − R*)/(R₀ − R*))]/c₀,
// R* = (n − 1)D/c₀. The integrator must agree with it (RK4, 64 substeps: ~1e-9 here).
TEST(GrowthFit, LawMatchesClosedForm) {
  const double c0 = 1.0, D = 4.0, R0 = 10.0, Rs = 8.0;
  const auto t = times(10, 3.0);
  const auto R = growth_law_radius(t, R0, c0, D, 3);
  for (std::size_t i = 1; i < t.size(); ++i)
    EXPECT_NEAR((R[i] - R0 + Rs * std::log((R[i] - Rs) / (R0 - Rs))) / c0, t[i], 1e-7) << i;
  // In 2D the curvature term is D/R: R* = D/c0.
  const auto R2 = growth_law_radius(t, R0, c0, D, 2);
  EXPECT_NEAR((R2[9] - R0 + 4.0 * std::log((R2[9] - 4.0) / (R0 - 4.0))) / c0, t[9], 1e-7);
}

// Exact data: the parameters come back to round-off; noisy data (σ = 0.05 Å, 200 draws): the
// standard errors describe the scatter — the fraction of fits within 2σ of the truth is
// 0.95 ± 0.05 (binomial: ±0.015 at 1σ for 200 draws, three of it), and the mean standard error
// of D is within 30% of the scatter of D (the linearised covariance of a 3-parameter fit).
TEST(GrowthFit, RecoversTheLawAndItsUncertainty) {
  const auto t = times(12, 1.5);
  const auto exact = growth_law_radius(t, 10.0, 1.0, 4.0, 3);
  const GrowthFit f = fit_growth_law(t, exact, 3, "exact");
  EXPECT_NEAR(f.c0, 1.0, 1e-8);
  EXPECT_NEAR(f.D, 4.0, 1e-7);
  EXPECT_NEAR(f.R0, 10.0, 1e-8);
  EXPECT_TRUE(f.converged);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.05);
  int inside = 0;
  double sum = 0, sum2 = 0, err = 0;
  const int draws = 200;
  for (int k = 0; k < draws; ++k) {
    auto R = exact;
    for (double& r : R) r += noise(rng);
    const GrowthFit g = fit_growth_law(t, R, 3, "noisy");
    inside += std::abs(g.D - 4.0) <= 2 * g.D_stderr && std::abs(g.c0 - 1.0) <= 2 * g.c0_stderr ? 1 : 0;
    sum += g.D, sum2 += g.D * g.D, err += g.D_stderr;
  }
  const double scatter = std::sqrt(sum2 / draws - (sum / draws) * (sum / draws));
  EXPECT_NEAR(err / draws / scatter, 1.0, 0.3);
  EXPECT_GE(inside, static_cast<int>(0.85 * draws));
}

// The decelerating growth of Xu et al. (2015)'s MD domains, R ∝ t^0.465, has a speed that rises
// with 1/R: the fit must give D < 0 (which bridge domain-growth refuses).
TEST(GrowthFit, PowerLawGrowthGivesNegativeD) {
  std::vector<double> t, R;
  for (int i = 1; i <= 8; ++i) t.push_back(2.0 * i), R.push_back(8.0 * std::pow(i, 0.465));
  const GrowthFit f = fit_growth_law(t, R, 3, "power");
  EXPECT_LT(f.D + 3 * f.D_stderr, 0.0);
}

TEST(GrowthFit, BadInput) {
  EXPECT_THROW(fit_growth_law({0, 1, 2}, {1, 2, 3}, 3, "three"), InputError);
  EXPECT_THROW(fit_growth_law({0, 1, 1, 2}, {1, 2, 3, 4}, 3, "repeated time"), InputError);
  EXPECT_THROW(fit_growth_law({0, 1, 2, 3}, {1, 2, NAN, 4}, 3, "nan"), InputError);
  EXPECT_THROW(fit_growth_law({0, 1, 2, 3}, {1, 2, 0, 4}, 3, "zero radius"), InputError);
}

}  // namespace
}  // namespace shockfield::phasefield
