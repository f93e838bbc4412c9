#include "shockfield/pd/bar_impact.hpp"

#include <cmath>

namespace shockfield::pd {

PointCloud bar_cloud(int points, double spacing) { return lattice_cloud(1, {points, 1, 1}, spacing); }

void set_impact_velocity(Simulation& sim, double velocity) {
  const auto& x = sim.cloud().x;
  const auto [lo, hi] = sim.cloud().bounds();
  const double middle = 0.5 * (lo[0] + hi[0]);
  for (std::size_t i = 0; i < x.size(); ++i) sim.velocities()[i] = Vec3(x[i][0] < middle ? velocity : 0.0, 0.0, 0.0);
}

double front_position(const std::vector<double>& x, const std::vector<double>& f, double level) {
  for (std::size_t k = f.size() - 1; k > 0; --k) {
    const double a = f[k] - level, b = f[k - 1] - level;
    if ((a < 0.0) != (b < 0.0) || b == 0.0) return x[k - 1] + (x[k] - x[k - 1]) * (b / (b - a));
  }
  return x.front();
}

double front_width(const std::vector<double>& x, const std::vector<double>& f, double amplitude) {
  return std::abs(front_position(x, f, 0.1 * amplitude) - front_position(x, f, 0.9 * amplitude));
}

}  // namespace shockfield::pd
