#include "shockfield/granular/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/contact_loop.hpp"

namespace shockfield::granular {
namespace {

// ω² bound of Gershgorin's theorem for the chain linearised at overlaps `overlap_of(k)`.
template <class Overlap>
double max_frequency_squared(const Chain& c, const HertzContact& law, Overlap&& overlap_of,
                             double wall_overlap) {
  const std::size_t n = c.size();
  double omega2 = 0.0;
  double k_above = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double k_below = i + 1 < n ? law.stiffness(c.kappa[i], overlap_of(i))
                                     : (c.has_wall ? law.stiffness(c.wall_kappa, wall_overlap) : 0.0);
    omega2 = std::max(omega2, 2.0 * (k_above + k_below) * c.inv_mass[i]);
    k_above = k_below;
  }
  return omega2;
}

}  // namespace

double Impulse::force_at(double t) const {
  if (kind != Kind::force || times.empty() || t < times.front() || t > times.back()) return 0.0;
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  if (it == times.end()) return forces.back();
  const auto j = static_cast<std::size_t>(it - times.begin());
  const double s = (t - times[j - 1]) / (times[j] - times[j - 1]);
  return forces[j - 1] + s * (forces[j] - forces[j - 1]);
}

double Impulse::energy_bound(const Chain& chain) const {
  if (kind == Kind::velocity) {
    double e = 0.0;
    for (long long i = 0; i < std::min<long long>(grains, static_cast<long long>(chain.size())); ++i)
      e += 0.5 * chain.mass[static_cast<std::size_t>(i)] * velocity * velocity;
    return e;
  }
  // A force history: the larger of the energy of its total impulse J given at once to grain 0,
  // J²/(2m₀), and the Hertz energy of contact 0 at twice the peak force.
  double impulse = 0.0, peak = 0.0;
  for (std::size_t j = 0; j < times.size(); ++j) {
    peak = std::max(peak, std::abs(forces[j]));
    if (j > 0) impulse += 0.5 * (forces[j] + forces[j - 1]) * (times[j] - times[j - 1]);
  }
  const double kappa = chain.kappa.front();
  const double x = std::cbrt(4.0 * peak * peak / (kappa * kappa));
  return std::max(impulse * impulse / (2.0 * chain.mass.front()), 0.4 * kappa * x * x * std::sqrt(x));
}

double Simulation::stable_step(const Chain& c, const Impulse& impulse) {
  const HertzContact law{c.damping};
  const double e = impulse.energy_bound(c);
  const auto dynamic = [e](double kappa) { return std::pow(2.5 * e / kappa, 0.4); };
  const double omega2 = max_frequency_squared(
      c, law, [&](std::size_t k) { return std::max(c.rest_overlap[k], 0.0) + dynamic(c.kappa[k]); },
      c.has_wall ? c.wall_rest_overlap + dynamic(c.wall_kappa) : 0.0);
  return omega2 > 0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
}

Simulation::Simulation(Chain chain, Impulse impulse, std::optional<double> time_step, double safety)
    : chain_(std::move(chain)), impulse_(std::move(impulse)), law_{chain_.damping} {
  const std::size_t n = chain_.size();
  if (impulse_.kind == Impulse::Kind::velocity && (impulse_.grains < 1 || impulse_.grains > static_cast<long long>(n)))
    throw InputError(fmt::format("the impulse spans {} grains of a chain of {}", impulse_.grains, n));
  if (impulse_.times.size() != impulse_.forces.size())
    throw InputError("the force history needs as many forces as times");
  for (std::size_t j = 1; j < impulse_.times.size(); ++j)
    if (!(impulse_.times[j] > impulse_.times[j - 1])) throw InputError("the force history's times must increase");
  const double stable = stable_step(chain_, impulse_);
  if (time_step) {
    if (!(*time_step > 0)) throw InputError("the time step must be positive");
    if (*time_step > stable)
      throw InputError(fmt::format("time step {:.6g} s is above the stable step {:.6g} s of the stiffest "
                                   "contact (docs/theory/granular.md)", *time_step, stable));
    dt_ = *time_step;
  } else {
    if (!std::isfinite(stable))
      throw InputError("nothing loads the chain, so no contact sets a time step: give one");
    dt_ = safety * stable;
  }
  w_.assign(n, 0.0);
  v_.assign(n, 0.0);
  f_.assign(n, 0.0);
  contact_force_.assign(n - 1, 0.0);
  if (impulse_.kind == Impulse::Kind::velocity)
    std::fill_n(v_.begin(), impulse_.grains, impulse_.velocity);
  top_force_ = impulse_.force_at(0.0);
  compute_forces();
}

void Simulation::compute_forces() {
  wall_force_ = chain_.has_wall ? law_.force(chain_.wall_kappa, wall_overlap(), v_.back()) : 0.0;
  const ChainArrays a{size(), w_.data(), v_.data(), chain_.kappa.data(), chain_.rest_overlap.data(),
                      chain_.mass.data(), contact_force_.data(), f_.data()};
  evaluate_chain_forces(law_, a, chain_.gravity, wall_force_, top_force_);
}

void Simulation::step() {
  const std::size_t n = size();
  const double half = 0.5 * dt_, dt = dt_;
  double* w = w_.data();
  double* v = v_.data();
  const double* f = f_.data();
  const double* inv_m = chain_.inv_mass.data();
  const bool threaded = n >= kThreadedGrains;
  const double w0_before = w_[0], push_before = top_force_;
#pragma omp parallel for simd schedule(static) if (threaded)
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += half * f[i] * inv_m[i];
    w[i] += dt * v[i];
  }
  time_ = static_cast<double>(steps_ + 1) * dt_;
  top_force_ = impulse_.force_at(time_);
  compute_forces();
#pragma omp parallel for simd schedule(static) if (threaded)
  for (std::size_t i = 0; i < n; ++i) v[i] += half * f[i] * inv_m[i];
  external_work_ += 0.5 * (push_before + top_force_) * (w_[0] - w0_before);
  ++steps_;
}

void Simulation::health_check() const {
  for (std::size_t i = 0; i < size(); ++i)
    if (!std::isfinite(w_[i]) || !std::isfinite(v_[i]))
      throw RunError(fmt::format("step {}: grain {} has a non-finite displacement or velocity", steps_, i));
  const double omega2 = max_frequency_squared(
      chain_, law_, [this](std::size_t k) { return overlap(k); }, chain_.has_wall ? wall_overlap() : 0.0);
  if (omega2 > 0 && dt_ > 2.0 / std::sqrt(omega2))
    throw RunError(fmt::format("step {}: the stiffest contact now needs a step below {:.6g} s, the run "
                               "uses {:.6g} s (the impulse is stronger than the stable-step estimate "
                               "assumed): give a smaller time_step",
                               steps_, 2.0 / std::sqrt(omega2), dt_));
}

double Simulation::excess_energy(std::size_t first, std::size_t last) const {
  double e = 0.0;
  for (std::size_t i = first; i < last; ++i) e += 0.5 * chain_.mass[i] * v_[i] * v_[i] - chain_.mass[i] * chain_.gravity * w_[i];
  for (std::size_t k = first; k + 1 < last; ++k)
    e += law_.energy(chain_.kappa[k], overlap(k)) - law_.energy(chain_.kappa[k], chain_.rest_overlap[k]);
  if (last == size() && chain_.has_wall)
    e += law_.energy(chain_.wall_kappa, wall_overlap()) - law_.energy(chain_.wall_kappa, chain_.wall_rest_overlap);
  return e;
}

Thermo Simulation::thermo() const {
  Thermo t;
  t.step = steps_;
  t.time = time_;
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < size(); ++i) {
    t.kinetic += 0.5 * chain_.mass[i] * v_[i] * v_[i];
    if (std::abs(v_[i]) > std::abs(v_[fastest])) fastest = i;
  }
  t.total = excess_energy(0, size());
  t.potential = t.total - t.kinetic;
  t.external_work = external_work_;
  t.signal_depth = position(fastest);
  return t;
}

void Simulation::restore(std::vector<double> w, std::vector<double> v, std::vector<double> force,
                         std::vector<double> contact_force, long long steps, double time,
                         double external_work) {
  if (w.size() != size() || v.size() != size() || force.size() != size() || contact_force.size() + 1 != size())
    throw InputError(fmt::format("checkpoint has {} grains, the case has {}", w.size(), size()));
  w_ = std::move(w);
  v_ = std::move(v);
  f_ = std::move(force);
  contact_force_ = std::move(contact_force);
  steps_ = steps;
  time_ = time;
  external_work_ = external_work;
  top_force_ = impulse_.force_at(time_);
  wall_force_ = chain_.has_wall ? law_.force(chain_.wall_kappa, wall_overlap(), v_.back()) : 0.0;
}

}  // namespace shockfield::granular
