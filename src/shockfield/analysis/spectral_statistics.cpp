#include "shockfield/analysis/spectral_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/fft.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

fft::Layout layout_of(const GridFieldView& f) {
  return {f.n, f.spacing, f.dimension()};
}

// |F(δΘ)|² on the half spectrum, with the mean removed and void cells at δΘ = 0.
std::vector<double> power(const GridFieldView& field) {
  validate(field, "field");
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < field.size(); ++i)
    if (!field.void_at(i)) sum += field.values[i], ++count;
  if (count == 0) throw InputError("field: every cell is void; no spectrum to take");
  const double mean = sum / double(count);
  std::vector<double> delta(field.size(), 0.0);
  for (std::size_t i = 0; i < field.size(); ++i)
    if (!field.void_at(i)) delta[i] = field.values[i] - mean;
  const auto spectrum = fft::forward(layout_of(field), delta);
  std::vector<double> p(spectrum.size());
  for (std::size_t c = 0; c < p.size(); ++c) p[c] = std::norm(spectrum[c]);
  return p;
}

// Adds value × weight at radius r to shell round(r / width); returns the averaged profile.
struct ShellSum {
  double width;
  std::vector<double> r, v, w;
  void add(double radius, double value, double weight) {
    const auto s = static_cast<std::size_t>(std::lround(radius / width));
    if (s >= v.size()) r.resize(s + 1, 0.0), v.resize(s + 1, 0.0), w.resize(s + 1, 0.0);
    r[s] += radius * weight, v[s] += value * weight, w[s] += weight;
  }
  RadialProfile profile(std::size_t first) const {
    RadialProfile out;
    for (std::size_t s = first; s < v.size(); ++s)
      if (w[s] > 0.0) {
        out.x.push_back(r[s] / w[s]);
        out.values.push_back(v[s] / w[s]);
        out.count.push_back(static_cast<std::size_t>(std::lround(w[s])));
      }
    return out;
  }
};

}  // namespace

RadialProfile structure_factor(const GridFieldView& field) {
  const fft::Layout l = layout_of(field);
  const std::vector<double> p = power(field);
  double longest = 0.0;
  for (int a = 0; a < l.dimension; ++a) longest = std::max(longest, double(l.n[a]) * l.spacing[a]);
  ShellSum shells{2.0 * std::numbers::pi / longest, {}, {}, {}};
  for (std::size_t c = 1; c < p.size(); ++c)
    shells.add(std::sqrt(l.k_squared(c)), p[c] / double(l.real_size()), l.multiplicity(c));
  return shells.profile(1);
}

RadialProfile correlation_function(const GridFieldView& field) {
  const fft::Layout l = layout_of(field);
  std::vector<double> p = power(field);
  std::vector<std::complex<double>> spectrum(p.begin(), p.end());
  const std::vector<double> c = fft::backward(l, std::move(spectrum));  // N² × ⟨δΘ δΘ⟩(r)
  if (!(c[0] > 0.0)) throw InputError("field: constant (zero variance); no correlation function");
  double h = l.spacing[0];
  for (int a = 1; a < l.dimension; ++a) h = std::min(h, l.spacing[a]);
  ShellSum shells{h, {}, {}, {}};
  for (std::size_t i = 0; i < c.size(); ++i) {
    double r2 = 0.0;
    std::size_t rest = i;
    for (int a = 0; a < 3; ++a) {
      const std::size_t j = rest % l.n[a];
      rest /= l.n[a];
      const double d = double(std::min(j, l.n[a] - j)) * l.spacing[a];  // periodic separation
      r2 += d * d;
    }
    shells.add(std::sqrt(r2), c[i] / c[0], 1.0);
  }
  return shells.profile(0);
}

double characteristic_size(const GridFieldView& field) {
  const fft::Layout l = layout_of(field);
  const std::vector<double> p = power(field);
  double num = 0.0, den = 0.0;
  for (std::size_t c = 1; c < p.size(); ++c) {
    num += l.multiplicity(c) * std::sqrt(l.k_squared(c)) * p[c];
    den += l.multiplicity(c) * p[c];
  }
  if (!(den > 0.0)) throw InputError("field: constant (zero variance); no domain size");
  return 2.0 * std::numbers::pi * den / num;
}

}  // namespace shockfield::analysis
