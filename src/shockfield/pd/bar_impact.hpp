#pragma once
// The paper's 1D impact model (Liu et al. 2025, Fig. 2): a laterally constrained bar whose left half moves
// at v towards the resting right half, and the measurements taken on it: axial stress profiles,
// the position of a wave front (where the stress first reaches a level, scanning from the far
// end) and its width.
#include <vector>

#include "shockfield/pd/point_cloud.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

/// A 1D bar of `points` points with spacing ΔX starting at x = 0.
PointCloud bar_cloud(int points, double spacing);
/// Left half (x below the middle) moves at +v, the rest rests.
void set_impact_velocity(Simulation& sim, double velocity);

/// Where the profile f(x) (x increasing) last crosses `level` when scanning from the end
/// (linear interpolation between points); the first x when it never does.
double front_position(const std::vector<double>& x, const std::vector<double>& f, double level);
/// Distance between the crossings of 10% and 90% of `amplitude` (the front's width).
double front_width(const std::vector<double>& x, const std::vector<double>& f, double amplitude);

}  // namespace shockfield::pd
