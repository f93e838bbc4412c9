#include "shockfield/dbm/phase_separation.hpp"

#include <array>
#include <cmath>

#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/analysis/spectral_statistics.hpp"
#include "shockfield/core/rng.hpp"

namespace shockfield::dbm {

Macro Quench::state(const Lattice& lattice, double x, double y) const {
  const auto i = static_cast<std::uint64_t>(std::floor(x / lattice.dx));
  const auto j = static_cast<std::uint64_t>(std::floor(y / lattice.dy));
  const double xi = 2.0 * rng::uniform(seed, i, j) - 1.0;
  return Macro{rho0 * (1.0 + noise * xi), 0.0, 0.0, T};
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
    if (s.D > e.D_max) e.D_max = s.D, e.t_sd = s.t;
    if (s.boundary_length > e.L_max) e.L_max = s.boundary_length, e.t_L_max = s.t;
  }
  return e;
}

}  // namespace shockfield::dbm
