#include "shockfield/granular/signal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::granular {

SignalFront measure_signal(const Simulation& sim, double edge_fraction) {
  const std::vector<double>& v = sim.velocity();
  const std::size_t n = v.size();
  double vmax = 0.0;
  for (double x : v) vmax = std::max(vmax, std::abs(x));
  SignalFront out;
  if (vmax == 0.0) return out;
  std::size_t edge = n - 1;
  while (edge > 0 && std::abs(v[edge]) < edge_fraction * vmax) --edge;
  std::size_t p = edge;
  while (p > 0 && v[p - 1] >= v[p]) --p;
  // Parabola through (p-1, p, p+1) for the peak's place and height.
  double pos = static_cast<double>(p), peak = v[p];
  if (p > 0 && p + 1 < n) {
    const double a = v[p - 1], b = v[p], c = v[p + 1];
    const double curv = a - 2 * b + c;
    if (curv < 0) {
      const double s = 0.5 * (a - c) / curv;
      pos += s;
      peak = b - 0.25 * (a - c) * s;
    }
  }
  const double half = 0.5 * peak;
  std::size_t lo = p, hi = p;
  while (lo > 0 && v[lo - 1] >= half) --lo;
  while (hi + 1 < n && v[hi + 1] >= half) ++hi;
  const double left = lo > 0 ? static_cast<double>(lo) - (v[lo] - half) / (v[lo] - v[lo - 1]) : 0.0;
  const double right = hi + 1 < n ? static_cast<double>(hi) + (v[hi] - half) / (v[hi] - v[hi + 1])
                                  : static_cast<double>(n - 1);
  const Chain& c = sim.chain();
  double force = 0.0;
  const std::size_t k_lo = lo > 0 ? lo - 1 : 0, k_hi = std::min(hi, c.contacts() - 1);
  for (std::size_t k = k_lo; k <= k_hi; ++k) force = std::max(force, sim.contact_force()[k] - sim.rest_force(k));
  const auto i0 = std::min(static_cast<std::size_t>(pos), n - 2);
  const double frac = pos - static_cast<double>(i0);
  out.valid = true;
  out.sample = {sim.time(), pos, c.depth[i0] + frac * (c.depth[i0 + 1] - c.depth[i0]), peak, force,
                right - left, 0.0};
  return out;
}

PeakTracker::PeakTracker(std::vector<std::size_t> grains)
    : grains_(std::move(grains)), before_(grains_.size(), 0.0), last_(grains_.size(), 0.0),
      best_(grains_.size()) {}

void PeakTracker::sample(const Simulation& sim) {
  const double t = sim.time();
  const double h = t - last_time_;
  for (std::size_t j = 0; j < grains_.size(); ++j) {
    const double now = sim.velocity()[grains_[j]];
    const double a = before_[j], b = last_[j];
    if (samples_ >= 2 && b >= a && b > now && b > best_[j].velocity) {
      // Vertex of the parabola through (t-2h, a), (t-h, b), (t, now).
      const double curv = a - 2 * b + now;
      const double s = 0.5 * (a - now) / curv;
      best_[j] = {last_time_ + s * h, b - 0.25 * (a - now) * s};
    }
    before_[j] = b;
    last_[j] = now;
  }
  last_time_ = t;
  ++samples_;
}

void fill_speeds(std::vector<SignalSample>& s) {
  const std::size_t n = s.size();
  for (std::size_t j = 0; j < n && n > 1; ++j) {
    const std::size_t a = j == 0 ? 0 : j - 1, b = j + 1 < n ? j + 1 : n - 1;
    s[j].speed = (s[b].depth - s[a].depth) / (s[b].time - s[a].time);
  }
}

std::vector<SignalSample> track_signal(Simulation& sim, double t_end, int count) {
  std::vector<SignalSample> samples;
  const auto every = std::max<long long>(1, static_cast<long long>(t_end / count / sim.time_step()));
  while (sim.time() < t_end) {
    sim.step();
    if (sim.step_count() % every == 0)
      if (const SignalFront f = measure_signal(sim); f.valid) samples.push_back(f.sample);
  }
  fill_speeds(samples);
  return samples;
}

double reflected_energy(const Simulation& sim, const Simulation& reference, std::size_t impurity,
                        std::size_t margin) {
  const std::size_t last = impurity > margin ? impurity - margin : 0;
  return sim.excess_energy(0, last) - reference.excess_energy(0, last);
}

PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 3 || y.size() != n) throw InputError(fmt::format("a power-law fit needs 3 or more (x, y) pairs, not {}", n));
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) throw InputError("a power-law fit needs positive x and y");
    mx += std::log(x[i]);
    my += std::log(y[i]);
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = std::log(x[i]) - mx;
    sxx += dx * dx;
    sxy += dx * (std::log(y[i]) - my);
  }
  PowerLaw fit;
  fit.exponent = sxy / sxx;
  const double intercept = my - fit.exponent * mx;
  double rss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::log(y[i]) - intercept - fit.exponent * std::log(x[i]);
    rss += r * r;
  }
  fit.exponent_error = std::sqrt(rss / static_cast<double>(n - 2) / sxx);
  fit.prefactor = std::exp(intercept);
  return fit;
}

}  // namespace shockfield::granular
