#include "shockfield/dbm/tne.hpp"

#include <cmath>

#include "shockfield/dbm/simulation.hpp"

namespace shockfield::dbm {

const std::array<std::string, kTneComponents> kTneNames{
    "D2xx", "D2xy", "D2yy", "D3xxx", "D3xxy", "D3xyy", "D3yyy", "D31x", "D31y", "D42xx", "D42xy",
    "D42yy"};

namespace {

// Multiplicity of each component in the full symmetric tensor (for the Frobenius norm).
constexpr std::array<double, kTneComponents> kMultiplicity{1, 2, 1, 1, 3, 3, 1, 1, 1, 1, 2, 1};

// Adds d·(moment weights of velocity (cx, cy) with internal η) to m.
void accumulate(double d, double cx, double cy, double eta, double* m) {
  const double half = 0.5 * (cx * cx + cy * cy + eta * eta);
  m[0] += d * cx * cx;
  m[1] += d * cx * cy;
  m[2] += d * cy * cy;
  m[3] += d * cx * cx * cx;
  m[4] += d * cx * cx * cy;
  m[5] += d * cx * cy * cy;
  m[6] += d * cy * cy * cy;
  m[7] += d * half * cx;
  m[8] += d * half * cy;
  m[9] += d * half * cx * cx;
  m[10] += d * half * cx * cy;
  m[11] += d * half * cy * cy;
}

}  // namespace

TneFields tne_measures(const VelocityModel& model, const Lattice& lattice,
                       const std::vector<double>& difference, const std::vector<Macro>& macro) {
  const int nx = lattice.nx, ny = lattice.ny;
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  const std::size_t N = lattice.cells();
  TneFields out;
  for (int q = 0; q < kTneComponents; ++q) {
    out.raw[q].assign(n, 0.0);
    out.central[q].assign(n, 0.0);
  }
  out.strength.assign(n, 0.0);
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t cell = lattice.at(i, j), id = i + static_cast<std::size_t>(nx) * j;
      const Macro& m = macro[id];
      std::array<double, kTneComponents> raw{}, central{};
      for (int k = 0; k < model.size(); ++k) {
        const double d = difference[k * N + cell];
        accumulate(d, model.vx[k], model.vy[k], model.eta[k], raw.data());
        accumulate(d, model.vx[k] - m.ux, model.vy[k] - m.uy, model.eta[k], central.data());
      }
      double d2 = 0.0;
      for (int q = 0; q < kTneComponents; ++q) {
        out.raw[q][id] = raw[q];
        out.central[q][id] = central[q];
        d2 += kMultiplicity[q] * central[q] * central[q];
      }
      out.strength[id] = std::sqrt(d2);
    }
  // Domain averages in a fixed order (thread-count independent).
  for (int q = 0; q < kTneComponents; ++q) {
    for (std::size_t id = 0; id < n; ++id) {
      out.mean_raw[q] += out.raw[q][id];
      out.mean_central[q] += out.central[q][id];
    }
    out.mean_raw[q] /= static_cast<double>(n);
    out.mean_central[q] /= static_cast<double>(n);
  }
  for (double d : out.strength) out.mean_strength += d;
  out.mean_strength /= static_cast<double>(n);
  return out;
}

TneFields tne_measures(const Simulation& sim) {
  const Lattice& lattice = sim.lattice();
  const int Q = sim.model().size();
  const std::size_t N = lattice.cells();
  std::vector<double> difference(sim.f().size(), 0.0);
  std::vector<Macro> macro(static_cast<std::size_t>(lattice.nx) * lattice.ny);
  std::vector<double> eq(Q);
  for (int j = 0; j < lattice.ny; ++j)
    for (int i = 0; i < lattice.nx; ++i) {
      const Macro m = sim.macro(i, j);
      macro[i + static_cast<std::size_t>(lattice.nx) * j] = m;
      sim.inversion().equilibrium(m.rho, m.ux, m.uy, m.T, sim.b(), eq.data());
      const std::size_t c = lattice.at(i, j);
      for (int k = 0; k < Q; ++k) difference[k * N + c] = sim.f()[k * N + c] - eq[k];
    }
  return tne_measures(sim.model(), lattice, difference, macro);
}

}  // namespace shockfield::dbm
