#include "shockfield/analysis/similarity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

double finite_or_zero(double v) { return std::isfinite(v) ? v : 0.0; }

void check_process(const Process& p, const char* what) {
  if (p.times.empty() || p.times.size() != p.points.size())
    throw InputError(fmt::format("{} process: {} times and {} points; expected the same number, "
                                 "at least one", what, p.times.size(), p.points.size()));
  for (std::size_t i = 1; i < p.times.size(); ++i)
    if (!(p.times[i] > p.times[i - 1]))
      throw InputError(fmt::format("{} process: times out of order ({} after {}); expected "
                                   "strictly increasing times", what, p.times[i], p.times[i - 1]));
}

}  // namespace

MorphologyPoint morphology_point(const Functionals2D& f, const GridFieldView& grid) {
  const double n = double(grid.size());
  return {f.area_fraction, f.boundary_length / (n * grid.spacing[0]),
          finite_or_zero(f.euler_per_black_node)};
}

MorphologyPoint morphology_point(const Functionals3D& f, const GridFieldView& grid) {
  const double n = double(grid.size()), h = grid.spacing[0];
  return {f.volume_fraction, f.surface_area / (n * h * h), f.mean_breadth / (n * h),
          finite_or_zero(f.euler_per_black_node)};
}

double distance(const MorphologyPoint& a, const MorphologyPoint& b) {
  if (a.size() != b.size())
    throw InputError(fmt::format("similarity: patterns with {} and {} functionals cannot be "
                                 "compared (2D and 3D mixed?)", a.size(), b.size()));
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (b[i] - a[i]) * (b[i] - a[i]);
  return std::sqrt(s);
}

double structural_similarity(const MorphologyPoint& a, const MorphologyPoint& b) {
  const double d = distance(a, b);
  return d > 0.0 ? 1.0 / d : std::numeric_limits<double>::infinity();
}

MorphologyPoint point_at(const Process& p, double t) {
  if (p.times.empty() || t < p.times.front() || t > p.times.back())
    throw InputError(fmt::format("similarity: time {} outside the process's range [{}, {}]", t,
                                 p.times.empty() ? 0.0 : p.times.front(),
                                 p.times.empty() ? 0.0 : p.times.back()));
  const auto hi = static_cast<std::size_t>(
      std::lower_bound(p.times.begin(), p.times.end(), t) - p.times.begin());
  if (p.times[hi] == t) return p.points[hi];
  const double w = (t - p.times[hi - 1]) / (p.times[hi] - p.times[hi - 1]);
  MorphologyPoint out(p.points[hi].size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = (1.0 - w) * p.points[hi - 1].at(i) + w * p.points[hi].at(i);
  return out;
}

double process_distance(const Process& a, const Process& b, double t1, double t2) {
  check_process(a, "first");
  check_process(b, "second");
  if (!(t2 > t1))
    throw InputError(fmt::format("similarity: time interval [{}, {}] is empty; expected t1 < t2",
                                 t1, t2));
  std::vector<double> t{t1, t2};
  for (const Process* p : {&a, &b})
    for (double s : p->times)
      if (s > t1 && s < t2) t.push_back(s);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  double integral = 0.0, previous = distance(point_at(a, t[0]), point_at(b, t[0]));
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double d = distance(point_at(a, t[i]), point_at(b, t[i]));
    integral += 0.5 * (d + previous) * (t[i] - t[i - 1]);
    previous = d;
  }
  return integral / (t2 - t1);
}

double dynamic_similarity(const Process& a, const Process& b, double t1, double t2) {
  const double d = process_distance(a, b, t1, t2);
  return d > 0.0 ? 1.0 / d : std::numeric_limits<double>::infinity();
}

ThresholdMatch match_threshold(const Process& reference, std::span<const double> thresholds,
                               const std::vector<Process>& candidates, double t1, double t2) {
  if (thresholds.empty() || thresholds.size() != candidates.size())
    throw InputError(fmt::format("similarity: {} thresholds for {} candidate processes",
                                 thresholds.size(), candidates.size()));
  ThresholdMatch m;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    m.distances.push_back(process_distance(reference, candidates[k], t1, t2));
    if (m.distances[k] < m.distances[m.index]) m.index = k;
  }
  m.threshold = thresholds[m.index];
  m.distance = m.distances[m.index];
  return m;
}

}  // namespace shockfield::analysis
