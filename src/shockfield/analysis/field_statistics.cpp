#include "shockfield/analysis/field_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {

Moments moments(const GridFieldView& field) {
  validate(field, "field");
  Moments m;
  double sum = 0.0;
  for (std::size_t i = 0; i < field.size(); ++i)
    if (!field.void_at(i)) sum += field.values[i], ++m.count;
  if (m.count == 0) throw InputError("field: every cell is void; no statistics to take");
  m.mean = sum / double(m.count);
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field.void_at(i)) continue;
    const double d = field.values[i] - m.mean, d2 = d * d;
    m2 += d2, m3 += d2 * d, m4 += d2 * d2;
  }
  m2 /= double(m.count), m3 /= double(m.count), m4 /= double(m.count);
  m.std = std::sqrt(m2);
  if (m2 > 0.0) m.skewness = m3 / (m2 * m.std), m.kurtosis = m4 / (m2 * m2);
  return m;
}

Histogram histogram(const GridFieldView& field, std::size_t bins, double lo, double hi) {
  validate(field, "field");
  if (bins == 0 || !(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi))
    throw InputError(fmt::format("histogram: {} bins over [{}, {}]; expected at least one bin and "
                                 "a finite range with lo < hi", bins, lo, hi));
  Histogram h;
  h.counts.assign(bins, 0);
  for (std::size_t b = 0; b <= bins; ++b) h.edges.push_back(lo + (hi - lo) * double(b) / double(bins));
  for (std::size_t i = 0; i < field.size(); ++i) {
    const double v = field.values[i];
    if (field.void_at(i) || v < lo || v > hi) continue;
    const auto b = std::min(bins - 1, static_cast<std::size_t>((v - lo) / (hi - lo) * double(bins)));
    ++h.counts[b];
  }
  return h;
}

Histogram histogram(const GridFieldView& field, std::size_t bins) {
  validate(field, "field");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < field.size(); ++i)
    if (!field.void_at(i)) lo = std::min(lo, field.values[i]), hi = std::max(hi, field.values[i]);
  if (!(hi > lo)) hi = lo + 1.0, lo -= 1.0;  // constant field: one centred range
  return histogram(field, bins, lo, hi);
}

}  // namespace shockfield::analysis
