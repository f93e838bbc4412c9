// Counter-based random numbers: reproducible, well distributed; durations formatted for humans.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/progress.hpp"
#include "shockfield/core/rng.hpp"

using namespace shockfield;

TEST(Rng, SameCounterSameNumberDifferentCounterDifferentNumber) {
  EXPECT_EQ(rng::uniform(7, 1, 2, 3), rng::uniform(7, 1, 2, 3));
  EXPECT_NE(rng::uniform(7, 1, 2, 3), rng::uniform(7, 1, 2, 4));
  EXPECT_NE(rng::uniform(7, 1, 2, 3), rng::uniform(8, 1, 2, 3));
}

TEST(Rng, NormalHasZeroMeanAndUnitVariance) {
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng::normal(42, static_cast<std::uint64_t>(i));
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  // Standard errors: 1/sqrt(n) = 0.0022 for the mean, sqrt(2/n) = 0.0032 for the variance.
  EXPECT_NEAR(mean, 0.0, 0.011);
  EXPECT_NEAR(var, 1.0, 0.016);
}

TEST(Progress, FormatsDurations) {
  EXPECT_EQ(format_duration(12.34), "12.3s");
  EXPECT_EQ(format_duration(185), "3m05s");
  EXPECT_EQ(format_duration(3720), "1h02m");
  EXPECT_EQ(format_duration(NAN), "?");
}
