#include "shockfield/analysis/shock_profile.hpp"

#include <algorithm>

namespace shockfield::analysis {

double front_crossing(std::span<const double> position, std::span<const double> value,
                      std::span<const double> weight, double level, int direction) {
  const auto n = static_cast<std::ptrdiff_t>(position.size());
  std::ptrdiff_t ahead = -1;  // the last occupied bin passed, ahead of the current one
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const std::ptrdiff_t b = direction > 0 ? n - 1 - k : k;
    const auto u = static_cast<std::size_t>(b);
    if (!(weight[u] > 0.0)) continue;
    if (value[u] >= level) {
      if (ahead < 0) return position[u];
      const auto a = static_cast<std::size_t>(ahead);
      // value[a] < level <= value[u]: the level's position on the line through the two bins.
      const double f = (value[u] - level) / (value[u] - value[a]);
      return position[u] + f * (position[a] - position[u]);
    }
    ahead = b;
  }
  return NAN;
}

WeightedMoments window_moments(std::span<const double> position, std::span<const double> value,
                       std::span<const double> weight, double lo, double hi) {
  if (lo > hi) std::swap(lo, hi);
  double w = 0.0, sum = 0.0;
  for (std::size_t b = 0; b < position.size(); ++b)
    if (weight[b] > 0.0 && position[b] >= lo && position[b] <= hi) w += weight[b], sum += weight[b] * value[b];
  WeightedMoments m;
  if (!(w > 0.0)) return m;
  m.weight = w;
  m.mean = sum / w;
  double var = 0.0;  // second pass about the mean: no cancellation
  for (std::size_t b = 0; b < position.size(); ++b)
    if (weight[b] > 0.0 && position[b] >= lo && position[b] <= hi) var += weight[b] * (value[b] - m.mean) * (value[b] - m.mean);
  m.std = std::sqrt(var / w);
  return m;
}

WeightedMoments pooled_moments(const std::vector<WeightedMoments>& parts) {
  double w = 0.0, sum = 0.0;
  for (const WeightedMoments& p : parts)
    if (p.weight > 0.0) w += p.weight, sum += p.weight * p.mean;
  WeightedMoments m;
  if (!(w > 0.0)) return m;
  m.weight = w;
  m.mean = sum / w;
  double var = 0.0;
  for (const WeightedMoments& p : parts)
    if (p.weight > 0.0) var += p.weight * (p.std * p.std + (p.mean - m.mean) * (p.mean - m.mean));
  m.std = std::sqrt(var / w);
  return m;
}

}  // namespace shockfield::analysis
