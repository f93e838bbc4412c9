#pragma once
// A van der Waals droplet of the GLS model relaxed in a periodic box, for the Laplace-law tests
// (tests/unit/dbm_gls/laplace_test.cpp, tests/validation/slow/test_dbm_laplace.cpp; why these
// settings: docs/theory/dbm.md, "Laplace law"). Δp is the jump of the normal stress
// P_xx = P(ρ, T) + Λ_xx between the droplet centre and the box corner (each at its own measured T;
// ∇ρ = 0 at both by symmetry, so Λ_xx = −Kρ∇²ρ there), averaged over the last part of the run:
// small droplets have no flat liquid core, and the bulk P alone misses Λ_xx (20% of Δp at
// R = 0.36 on Δx = 0.04). R is the equimolar radius of the measured centre and corner densities.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "shockfield/dbm/coexistence.hpp"
#include "shockfield/dbm/spectral.hpp"
#include "unit/dbm_gls/gls_setup.hpp"

namespace shockfield::dbm::gls_testing {

struct LaplaceCase {
  int cells = 48;           // per side
  double box = 2.0;         // side of the periodic box; the droplet sits at its centre
  double K = 1e-3, T = 0.9;
  double tau = 5e-4;        // spurious currents and the Δp offset grow with τ
  double dt = 1e-3, zeta = 0.2;  // ζ damps the breathing (0.1: slow oscillation, 0.4: slow creep)
  double q = -0.1;          // conductivity 2ρT(τ − q) ≈ 200× BGK: T stays uniform (eq. 18)
  double t_end = 1.4, t_average = 0.7;  // Δp averaged over [t_average, t_end], every 0.1
};

struct Droplet {
  double radius = 0, dp = 0;
  double T_mean = 0, T_spread = 0;   // mean and largest (max − min) of T over the window
  double T_interface = 0;            // T weighted by |∇ρ|² (where the tension sits), window mean
  double u_max = 0;                  // largest |u| over the window (spurious velocity)
  double mass_drift = 0, energy_drift = 0;  // relative, start to end (e_T of eq. 19)
};

inline Droplet relax_droplet(const LaplaceCase& lc, double r0) {
  const materials::VanDerWaals vdw;
  const Coexistence co = maxwell_construction(vdw, lc.T);
  GlsCase c;
  c.nx = c.ny = lc.cells, c.length = lc.box, c.K = lc.K, c.tau = lc.tau, c.dt = lc.dt, c.zeta = lc.zeta,
  c.q = lc.q, c.T = lc.T;
  const double centre = 0.5 * lc.box;
  GlsRun run = make_gls(c, [&](double x, double y) {
    const double s = 0.5 * (1.0 - std::tanh((std::hypot(x - centre, y - centre) - r0) / 0.1));
    return Macro{co.rho_vapour + (co.rho_liquid - co.rho_vapour) * s, 0, 0, lc.T};
  });
  const double mass0 = run.sim->totals()[0], energy0 = run.force->energy().total();
  const int steps = static_cast<int>(std::lround(lc.t_end / lc.dt));
  const int first = static_cast<int>(std::lround(lc.t_average / lc.dt));
  const int every = static_cast<int>(std::lround(0.1 / lc.dt));
  const int mid = lc.cells / 2;  // the cell whose corner is the box centre
  const double dx = lc.box / lc.cells;
  const PeriodicSpectral spectral(lc.cells, lc.cells, dx, dx);
  std::vector<double> rho(spectral.size()), temperature(spectral.size());
  Droplet d;
  double liquid = 0, vapour = 0;
  int samples = 0;
  for (int s = 1; s <= steps; ++s) {
    run.sim->step();
    if (s < first || (s - first) % every != 0) continue;
    run.sim->check_state();
    double lo = INFINITY, hi = -INFINITY, sum = 0;
    for (int j = 0; j < lc.cells; ++j)
      for (int i = 0; i < lc.cells; ++i) {
        const Macro m = run.sim->macro(i, j);
        rho[i + lc.cells * j] = m.rho, temperature[i + lc.cells * j] = m.T;
        lo = std::min(lo, m.T), hi = std::max(hi, m.T), sum += m.T;
        d.u_max = std::max(d.u_max, std::hypot(m.ux, m.uy));
      }
    const auto rho_k = spectral.forward(rho);
    const std::vector<double> laplacian = spectral.laplacian(rho_k);
    const std::vector<double> rx = spectral.derivative(rho_k, 1, 0), ry = spectral.derivative(rho_k, 0, 1);
    double weight = 0, weighted = 0;
    for (int j = 0; j < lc.cells; ++j)
      for (int i = 0; i < lc.cells; ++i) {
        const std::size_t c = i + static_cast<std::size_t>(lc.cells) * j;
        const double g2 = rx[c] * rx[c] + ry[c] * ry[c];
        weight += g2, weighted += g2 * temperature[c];
      }
    d.T_interface += weighted / weight;
    const auto normal_stress = [&](int i) {  // at cell (i, i), where ∇ρ = 0
      const Macro m = run.sim->macro(i, i);
      return vdw.pressure(m.rho, m.T) - lc.K * m.rho * laplacian[i + lc.cells * i];
    };
    d.dp += normal_stress(mid) - normal_stress(0);
    liquid += rho[mid + lc.cells * mid], vapour += rho[0];
    d.T_mean += sum / (lc.cells * lc.cells), d.T_spread = std::max(d.T_spread, hi - lo);
    ++samples;
  }
  d.dp /= samples, liquid /= samples, vapour /= samples, d.T_mean /= samples, d.T_interface /= samples;
  const double mass = run.sim->totals()[0];
  const double area = (mass - vapour * lc.box * lc.box) / (liquid - vapour);  // equimolar
  d.radius = std::sqrt(area / std::numbers::pi);
  d.mass_drift = std::abs(mass / mass0 - 1.0);
  d.energy_drift = std::abs(run.force->energy().total() / energy0 - 1.0);
  return d;
}

/// Each droplet relaxed, with its line printed.
inline std::vector<Droplet> relax_droplets(const LaplaceCase& lc, const std::vector<double>& radii) {
  std::vector<Droplet> drops;
  for (double r0 : radii) {
    const Droplet d = relax_droplet(lc, r0);
    std::printf("R0 = %.2f  R = %.4f  dp = %.6f  T mean %.5f, interface %.5f, spread %.4f  max|u| = %.4f  "
                "mass drift %.1e  e_T drift %.1e\n",
                r0, d.radius, d.dp, d.T_mean, d.T_interface, d.T_spread, d.u_max, d.mass_drift, d.energy_drift);
    drops.push_back(d);
  }
  return drops;
}

/// The square-gradient tension at the droplet's interface temperature (coexistence.hpp).
inline double reference_tension(const LaplaceCase& lc, const Droplet& d) {
  return interface_tension(materials::VanDerWaals{}, d.T_interface, lc.K);
}

/// Least-squares line Δp = slope/R + intercept through the droplets, against the mean reference
/// tension (printed with Δp·R/σ of each droplet).
struct LaplaceFit {
  double slope = 0, intercept = 0, sigma = 0;
};

inline LaplaceFit fit_laplace(const LaplaceCase& lc, const std::vector<Droplet>& drops) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(drops.size());
  LaplaceFit f;
  for (const Droplet& d : drops) {
    const double x = 1.0 / d.radius;
    sx += x, sy += d.dp, sxx += x * x, sxy += x * d.dp;
    f.sigma += reference_tension(lc, d) / n;
    std::printf("R = %.4f  dp*R/sigma = %.4f\n", d.radius, d.dp * d.radius / reference_tension(lc, d));
  }
  f.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  f.intercept = (sy - f.slope * sx) / n;
  std::printf("fit dp = s/R + c: s = %.6f (mean sigma %.6f, ratio %.4f), c = %.2e (%.1f%% of the smallest dp)\n",
              f.slope, f.sigma, f.slope / f.sigma, f.intercept, 100 * f.intercept / drops.back().dp);
  return f;
}

}  // namespace shockfield::dbm::gls_testing
