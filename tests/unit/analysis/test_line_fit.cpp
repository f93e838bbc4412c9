// Least-squares lines of the Hugoniot sweep on synthetic data with known answers: a hand-worked
// four-point fit, an exact copper-like Hugoniot, the standard error against the Monte Carlo
// spread of fits to noisy data, the front fit window, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/analysis/line_fit.hpp"

using namespace shockfield;
using namespace shockfield::analysis;

TEST(UsUpFit, HandWorkedFourPoints) {
  // x̄ = 1.5, ȳ = 2.75, Sxx = 5, Sxy = 5.5 → slope 1.1, intercept 1.1; residuals −0.1, 0.8,
  // −1.3, 0.6 → χ² = 2.7; σ_slope = √(2.7/2/5), σ_intercept = σ_slope·√(14/4).
  const LineFit f = fit_line({0, 1, 2, 3}, {1, 3, 2, 5});
  EXPECT_NEAR(f.slope, 1.1, 1e-14);
  EXPECT_NEAR(f.intercept, 1.1, 1e-14);
  EXPECT_NEAR(f.slope_stderr, std::sqrt(0.27), 1e-14);
  EXPECT_NEAR(f.intercept_stderr, std::sqrt(0.27) * std::sqrt(3.5), 1e-14);
  EXPECT_NEAR(f.residual_rms, std::sqrt(2.7 / 4), 1e-14);
  EXPECT_EQ(f.points, 4);
}

TEST(UsUpFit, ExactCopperHugoniot) {
  const std::vector<double> up{0.5, 1.0, 1.5, 2.0};
  std::vector<double> us;
  for (double u : up) us.push_back(3.94 + 1.49 * u);
  const UsUpFit f = fit_us_up(up, us);
  EXPECT_NEAR(f.c0(), 3.94, 1e-13);
  EXPECT_NEAR(f.s(), 1.49, 1e-13);
  EXPECT_NEAR(f.line.slope_stderr, 0.0, 1e-12);
  EXPECT_NE(us_up_fit_toml(f).find("c0_km_s = 3.94"), std::string::npos);
}

TEST(UsUpFit, StandardErrorsMatchMonteCarloSpread) {
  // 4000 sweeps with Gaussian noise σ = 0.05 km/s on U_s: the spread of the fitted c0 and s is
  // σ/√Sxx and σ√(Σx²/n/Sxx) (Sxx = 1.25, Σx²/n = 1.875), and so is the rms reported error.
  // 4000 fits: about ±1.5% sampling error on a spread.
  const std::vector<double> up{0.5, 1.0, 1.5, 2.0};
  const double sigma = 0.05;
  const int trials = 4000;
  double s_sum = 0, s_sq = 0, c_sum = 0, c_sq = 0, s_err = 0;
  for (int k = 0; k < trials; ++k) {
    std::vector<double> us;
    for (std::size_t i = 0; i < up.size(); ++i)
      us.push_back(3.94 + 1.49 * up[i] + sigma * rng::normal(7, static_cast<std::uint64_t>(k), i));
    const UsUpFit f = fit_us_up(up, us);
    s_sum += f.s();
    s_sq += f.s() * f.s();
    c_sum += f.c0();
    c_sq += f.c0() * f.c0();
    s_err += f.line.slope_stderr * f.line.slope_stderr;
  }
  const double s_mean = s_sum / trials, c_mean = c_sum / trials;
  const double s_spread = std::sqrt(s_sq / trials - s_mean * s_mean);
  const double c_spread = std::sqrt(c_sq / trials - c_mean * c_mean);
  EXPECT_NEAR(s_mean, 1.49, 4 * sigma / std::sqrt(1.25) / std::sqrt(trials));
  EXPECT_NEAR(c_mean, 3.94, 4 * sigma * std::sqrt(1.875 / 1.25) / std::sqrt(trials));
  EXPECT_NEAR(s_spread, sigma / std::sqrt(1.25), 0.05 * sigma / std::sqrt(1.25));
  EXPECT_NEAR(c_spread, sigma * std::sqrt(1.875 / 1.25), 0.05 * sigma * std::sqrt(1.875 / 1.25));
  // E[χ²/(n−2)] = σ²: the mean squared reported error is unbiased.
  EXPECT_NEAR(std::sqrt(s_err / trials), sigma / std::sqrt(1.25), 0.05 * sigma / std::sqrt(1.25));
}

TEST(UsUpFit, FrontFitUsesTheLastSeventyPercentAndSkipsMissingFronts) {
  // Front at 40 Å/ps after t = 3 ps; before that a transient the fit must not see.
  std::vector<double> t, x;
  for (int k = 0; k <= 10; ++k) {
    t.push_back(k);
    x.push_back(k < 3 ? 0.0 : 5.0 + 40.0 * k);
  }
  x[6] = NAN;
  const LineFit f = fit_shock_front(t, x);
  EXPECT_EQ(f.points, 7);  // t = 3..10 without t = 6
  EXPECT_NEAR(f.slope, 40.0, 1e-12);
  EXPECT_NEAR(f.intercept, 5.0, 1e-10);
}

TEST(UsUpFit, BadInput) {
  EXPECT_THROW(fit_line({1.0}, {2.0}), InputError);
  EXPECT_THROW(fit_line({1.0, 2.0}, {2.0}), InputError);
  EXPECT_THROW(fit_line({1.0, 1.0, 1.0}, {2.0, 3.0, 4.0}), InputError);
  const LineFit two = fit_line({0.0, 1.0}, {1.0, 3.0});
  EXPECT_DOUBLE_EQ(two.slope, 2.0);
  EXPECT_TRUE(std::isnan(two.slope_stderr));
}
