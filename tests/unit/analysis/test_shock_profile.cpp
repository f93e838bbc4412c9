// The generic 1D profile routines of a shock-front analysis (analysis/shock_profile.hpp), on
// profiles whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shockfield/analysis/shock_profile.hpp"

using namespace shockfield::analysis;

// A front running up (+1) is found scanning from the top: the first slab at or above the level
// and the occupied one above it, on a straight line. 8 → 2 between centres 2.5 and 3.5: level 5
// at 3.0; level 8 exactly on a centre; an empty slab (weight 0) is stepped over, the line then
// joins the occupied neighbours.
TEST(ShockProfile, FrontCrossingInterpolatesFromTheUndisturbedSide) {
  const std::vector<double> x{0.5, 1.5, 2.5, 3.5, 4.5}, v{9, 9, 8, 2, 0}, w{1, 1, 1, 1, 1};
  EXPECT_DOUBLE_EQ(front_crossing(x, v, w, 5.0, +1), 3.0);
  EXPECT_DOUBLE_EQ(front_crossing(x, v, w, 8.0, +1), 2.5);
  EXPECT_TRUE(std::isnan(front_crossing(x, v, w, 10.0, +1)));
  const std::vector<double> gap{1, 1, 1, 0, 1};
  EXPECT_DOUBLE_EQ(front_crossing(x, v, gap, 4.0, +1), 2.5 + (8.0 - 4.0) / 8.0 * 2.0);
  // Running down (−1): scanned from the bottom; the mirrored profile gives the mirrored position.
  const std::vector<double> down{0, 2, 8, 9, 9};
  EXPECT_DOUBLE_EQ(front_crossing(x, down, w, 5.0, -1), 2.0);
  // The first slab scanned is already shocked: its centre (nothing ahead to interpolate with).
  EXPECT_DOUBLE_EQ(front_crossing(x, std::vector<double>{9, 9, 9, 9, 9}, w, 5.0, +1), 4.5);
}

// Weighted mean and population std over [lo, hi] (either order), empty slabs and slabs outside
// left out; no slab: weight 0 and NaN.
TEST(ShockProfile, WindowAndPooledMoments) {
  const std::vector<double> x{0, 1, 2, 3, 4}, v{100, 1, 3, 5, -7}, w{1, 1, 3, 0, 1};
  const WeightedMoments m = window_moments(x, v, w, 3.5, 1.0);  // slabs 1, 2 (3 is empty)
  EXPECT_DOUBLE_EQ(m.weight, 4.0);
  EXPECT_DOUBLE_EQ(m.mean, (1.0 + 9.0) / 4.0);
  EXPECT_DOUBLE_EQ(m.std, std::sqrt((1.0 * 1.5 * 1.5 + 3.0 * 0.5 * 0.5) / 4.0));
  const WeightedMoments none = window_moments(x, v, w, 2.5, 3.5);
  EXPECT_EQ(none.weight, 0.0);
  EXPECT_TRUE(std::isnan(none.mean));
  // Pooling two windows equals the moments of their union.
  const WeightedMoments a = window_moments(x, v, w, 0.0, 1.0), b = window_moments(x, v, w, 2.0, 4.0);
  const WeightedMoments all = window_moments(x, v, w, 0.0, 4.0), pooled = pooled_moments({a, b, none});
  EXPECT_DOUBLE_EQ(pooled.weight, all.weight);
  EXPECT_NEAR(pooled.mean, all.mean, 1e-12 * std::abs(all.mean));
  EXPECT_NEAR(pooled.std, all.std, 1e-12 * all.std);
}
