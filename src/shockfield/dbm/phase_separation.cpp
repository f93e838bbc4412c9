#include "shockfield/dbm/phase_separation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/analysis/spectral_statistics.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"

namespace shockfield::dbm {

QuenchNoise::QuenchNoise(std::uint64_t seed, double shortest_wavelength, const Lattice& lattice)
    : seed_(seed), lattice_(lattice) {
  if (shortest_wavelength <= 0.0) return;
  if (shortest_wavelength < 2.0 * std::max(lattice.dx, lattice.dy))
    throw InputError(fmt::format("quench noise: the shortest wavelength {} is below two cells ({}): the grid cannot "
                                 "hold its modes", shortest_wavelength, 2.0 * std::max(lattice.dx, lattice.dy)));
  const double Lx = lattice.nx * lattice.dx, Ly = lattice.ny * lattice.dy;
  // The relative slack keeps a mode on the cutoff circle on every grid of the box (Lx = nx dx rounds).
  const double cut2 = (1.0 + 1e-9) / (shortest_wavelength * shortest_wavelength);
  const int mx = static_cast<int>(Lx / shortest_wavelength) + 1, my = static_cast<int>(Ly / shortest_wavelength) + 1;
  double power = 0.0;
  for (int n = 0; n <= my; ++n)
    for (int m = -mx; m <= mx; ++m) {
      if ((n == 0 && m <= 0) || (m / Lx) * (m / Lx) + (n / Ly) * (n / Ly) > cut2) continue;
      const auto a = static_cast<std::uint64_t>(static_cast<std::int64_t>(m)), b = static_cast<std::uint64_t>(n);
      const double amplitude = rng::normal(seed, a, b, 0);
      modes_.push_back({2.0 * std::numbers::pi * m / Lx, 2.0 * std::numbers::pi * n / Ly, amplitude,
                        2.0 * std::numbers::pi * rng::uniform(seed, a, b, 2)});
      power += 0.5 * amplitude * amplitude;
    }
  const double scale = 1.0 / std::sqrt(3.0 * power);
  for (Mode& mode : modes_) mode.amplitude *= scale;
}

double QuenchNoise::operator()(double x, double y) const {
  if (modes_.empty()) {
    const auto i = static_cast<std::uint64_t>(std::floor(x / lattice_.dx));
    const auto j = static_cast<std::uint64_t>(std::floor(y / lattice_.dy));
    return 2.0 * rng::uniform(seed_, i, j) - 1.0;
  }
  double xi = 0.0;
  for (const Mode& m : modes_) xi += m.amplitude * std::cos(m.kx * x + m.ky * y + m.phase);
  return xi;
}

std::pair<double, double> QuenchNoise::extremes_on_cells() const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int j = 0; j < lattice_.ny; ++j)
    for (int i = 0; i < lattice_.nx; ++i) {
      const double xi = (*this)(lattice_.x(i), lattice_.y(j));
      lo = std::min(lo, xi), hi = std::max(hi, xi);
    }
  return {lo, hi};
}

Macro Quench::state(const QuenchNoise& xi, double x, double y) const {
  return Macro{rho0 * (1.0 + noise * xi(x, y)), 0.0, 0.0, T};
}

analysis::GridField density_field(const Simulation& simulation) {
  const Lattice& L = simulation.lattice();
  analysis::GridField field = analysis::GridField::filled(L.nx, L.ny, 1, 0.0);
  field.spacing = {L.dx, L.dy, 1.0};
  for (int j = 0; j < L.ny; ++j)
    for (int i = 0; i < L.nx; ++i) field.values[field.index(i, j)] = simulation.macro(i, j).rho;
  return field;
}

PhaseSample sample_phase_separation(const Simulation& simulation, GlsForce& force,
                                    double threshold) {
  PhaseSample s;
  s.t = simulation.time();
  const GlsTne tne = force.tne();
  s.D = tne.net.mean_strength;
  s.D_force = tne.force.mean_strength;
  s.D_gradient = tne.gradient.mean_strength;
  const analysis::GridField rho = density_field(simulation);
  double mean = 0.0;
  for (double r : rho.values) mean += r;
  mean /= static_cast<double>(rho.size());
  for (double r : rho.values) s.density_variance += (r - mean) * (r - mean);
  s.density_variance /= static_cast<double>(rho.size());
  const std::array<double, 1> thresholds{threshold};
  s.boundary_length = analysis::minkowski_2d(rho, thresholds)[0].boundary_length;
  s.domain_size = s.density_variance > 0.0 ? analysis::characteristic_size(rho) : 0.0;
  s.mass = simulation.totals()[0];
  s.energy = force.energy().total();
  return s;
}

SpinodalEnd spinodal_end(const std::vector<PhaseSample>& samples) {
  SpinodalEnd e;
  for (const PhaseSample& s : samples) {
    if (s.D > e.D_max) e.D_max = s.D, e.t_sd = s.t, e.R_sd = s.domain_size;
    if (s.boundary_length > e.L_max) e.L_max = s.boundary_length, e.t_L_max = s.t;
  }
  return e;
}

DomainGrowth domain_growth(const std::vector<PhaseSample>& samples, double t_sd, double window) {
  // Sample times carry the round-off of n·Δt (and 10 digits in series.csv): a relative slack.
  const double slack = 1e-9 * (1.0 + std::abs(t_sd) + window);
  std::vector<const PhaseSample*> in;
  for (const PhaseSample& s : samples)
    if (s.t >= t_sd - slack && s.t <= t_sd + window + slack) in.push_back(&s);
  DomainGrowth g{std::numeric_limits<double>::quiet_NaN(), t_sd, t_sd};
  if (in.empty()) return g;
  g.t_end = in.back()->t;
  if (in.size() < 3) return g;
  // Least squares R = a + u_DG t about the window's mean time (no cancellation at late t).
  double t_mean = 0.0, R_mean = 0.0;
  for (const PhaseSample* s : in) t_mean += s->t, R_mean += s->domain_size;
  t_mean /= static_cast<double>(in.size()), R_mean /= static_cast<double>(in.size());
  double stt = 0.0, stR = 0.0;
  for (const PhaseSample* s : in) {
    const double dt = s->t - t_mean;
    stt += dt * dt, stR += dt * (s->domain_size - R_mean);
  }
  g.speed = stR / stt;
  return g;
}

}  // namespace shockfield::dbm
