#pragma once
// What a shock-front analysis reads from a 1D profile along the shock axis, for any method that
// bins its particles, atoms or cells into slabs along that axis (MPM's shock-front tool,
// mpm/shock_front.hpp):
//  - front_crossing: where the profile first reaches a level, looking from the undisturbed side
//    (the side the front runs towards), with the position interpolated linearly between the
//    centres of the two occupied bins around the crossing (a sub-bin position);
//  - window_moments: the weighted mean and standard deviation over the bins in a window, and
//    pooled_moments, those of several windows (frames) taken together.
// Bins of zero weight are empty (a void, or beyond the material) and are skipped.
#include <cmath>
#include <span>
#include <vector>

namespace shockfield::analysis {

/// Position where `value` first reaches `level` (value ≥ level), scanning the occupied bins
/// (weight > 0) from the undisturbed end: the high end of `position` for `direction` +1 (a front
/// running towards increasing position), the low end for −1. `value` is oriented so that the
/// shocked state lies above the level (a compressive stress, the particle velocity along the
/// front's direction). Linear interpolation between the crossing bin's centre and that of the
/// occupied bin ahead of it; the crossing bin's centre when there is none ahead. NaN when no bin
/// reaches the level. `position` increases; the three spans have one entry per bin.
double front_crossing(std::span<const double> position, std::span<const double> value,
                      std::span<const double> weight, double level, int direction);

/// Weighted mean and population standard deviation; weight 0 (and NaN moments) for no bins.
struct WeightedMoments {
  double mean = NAN;
  double std = NAN;
  double weight = 0.0;
};

/// WeightedMoments of `value` over the occupied bins whose centres lie in [lo, hi] (either order).
WeightedMoments window_moments(std::span<const double> position, std::span<const double> value,
                       std::span<const double> weight, double lo, double hi);

/// The moments of the union of several windows from theirs: the weighted mean of the means, and
/// the spread within the windows and between their means together (σ² = Σw(σ_k² + (μ_k − μ)²)/Σw).
WeightedMoments pooled_moments(const std::vector<WeightedMoments>& parts);

}  // namespace shockfield::analysis
