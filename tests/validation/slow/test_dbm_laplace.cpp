// Laplace law Δp = σ/R of the GLS liquid–vapour model (seed 000 §2.3.2, eqs. 13–19; issue 6):
// van der Waals droplets (T = 0.9, K = 1e-3) of initial radius 0.45, 0.6, 0.75 in a periodic box
// of 2 (64², Δx = 1/32; ζ = 0.1 damps the breathing modes). The surface tension comes from the
// simulated flat interface, σ = K∫(dρ/dx)² dx (the square-gradient tension, docs/theory/dbm.md),
// and is checked against the square-gradient integral ∫sqrt(2Kω)dρ at the slab's mean T within
// 10% (measured 0.005152 against 0.005521, −6.7%: not explained yet, see docs/theory/dbm.md). Δp is the bulk pressure
// P(ρ, T) at the droplet centre minus that at the box corner, averaged over t in [2, 4]; R is the
// equimolar radius of the measured liquid and vapour densities. Tolerance: Δp·R within 10% of σ
// for every radius, and the relative spread of Δp·R over the radii within 10% (the width of the
// interface, ≈ 0.2, is not small against R: the curvature corrections are of order width/R).
// Spurious velocities (largest |u| over the averaging window) are reported. Measured
// (OMP_NUM_THREADS=1, ~5 min per droplet on a loaded machine): R = 0.458, 0.606, 0.754 give
// Δp·R/σ = 0.966, 0.946, 0.911 with max|u| = 0.031, 0.032, 0.028.
// Label "slow": about 3 × 4000 steps of 64² cells plus a flat slab.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "shockfield/dbm/coexistence.hpp"
#include "shockfield/dbm/gls.hpp"
#include "unit/dbm_gls/gls_setup.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

constexpr double kT = 0.9, kK = 1e-3, kBox = 2.0;

gls_testing::GlsCase droplet_case(int ny) {
  gls_testing::GlsCase c;
  c.nx = 64, c.ny = ny, c.length = kBox, c.K = kK, c.tau = 1e-3, c.dt = 1e-3, c.zeta = 0.1, c.T = kT;
  return c;
}

// Tension of the simulated flat interface: a slab of width 1 in the box of 2, relaxed to t = 3.
struct Flat {
  double sigma = 0, T = 0;
};
Flat flat_interface_tension(const Coexistence& co) {
  const gls_testing::GlsCase c = droplet_case(4);
  auto run = gls_testing::make_gls(c, [&](double x, double) {
    const double s = 0.5 * (std::tanh((x - 0.5) / 0.1) - std::tanh((x - 1.5) / 0.1));
    return Macro{co.rho_vapour + (co.rho_liquid - co.rho_vapour) * s, 0, 0, kT};
  });
  for (int s = 0; s < 3000; ++s) run.sim->step();
  run.sim->check_state();
  std::vector<double> rho(c.nx);
  Flat flat;
  for (int i = 0; i < c.nx; ++i) rho[i] = run.sim->macro(i, 0).rho, flat.T += run.sim->macro(i, 0).T / c.nx;
  // dρ/dx by FFT of the periodic row (the model's own derivative), ∫ over both interfaces / 2.
  double integral = 0.0;
  const double dx = kBox / c.nx;
  for (int i = 0; i < c.nx; ++i) {
    double d = 0.0;  // spectral derivative of a real periodic sequence, direct sum
    for (int m = 1; m < c.nx / 2; ++m) {
      double re = 0.0, im = 0.0;
      for (int j = 0; j < c.nx; ++j) {
        const double a = 2.0 * std::numbers::pi * m * j / c.nx;
        re += rho[j] * std::cos(a), im -= rho[j] * std::sin(a);
      }
      const double k = 2.0 * std::numbers::pi * m / kBox, a = 2.0 * std::numbers::pi * m * i / c.nx;
      d += 2.0 / c.nx * k * (-re * std::sin(a) - im * std::cos(a));
    }
    integral += d * d * dx;
  }
  flat.sigma = 0.5 * kK * integral;
  return flat;
}

struct Droplet {
  double dp = 0, radius = 0, spurious = 0;
};

Droplet run_droplet(double r0, const Coexistence& co, const materials::VanDerWaals& vdw) {
  const gls_testing::GlsCase c = droplet_case(64);
  auto run = gls_testing::make_gls(c, [&](double x, double y) {
    const double r = std::hypot(x - 1.0, y - 1.0);
    const double s = 0.5 * (1.0 - std::tanh((r - r0) / 0.1));
    return Macro{co.rho_vapour + (co.rho_liquid - co.rho_vapour) * s, 0, 0, kT};
  });
  Droplet d;
  int samples = 0;
  double liquid = 0, vapour = 0, mass = 0;
  for (int s = 1; s <= 4000; ++s) {
    run.sim->step();
    if (s >= 2000 && s % 50 == 0) {
      run.sim->check_state();
      const Macro in = run.sim->macro(32, 32), out = run.sim->macro(0, 0);  // centre (1, 1), corner
      d.dp += vdw.pressure(in.rho, in.T) - vdw.pressure(out.rho, out.T);
      liquid += in.rho, vapour += out.rho;
      for (int j = 0; j < c.ny; ++j)
        for (int i = 0; i < c.nx; ++i) {
          const Macro m = run.sim->macro(i, j);
          d.spurious = std::max(d.spurious, std::hypot(m.ux, m.uy));
        }
      ++samples;
    }
  }
  d.dp /= samples, liquid /= samples, vapour /= samples;
  mass = run.sim->totals()[0];
  const double area = (mass - vapour * kBox * kBox) / (liquid - vapour);  // equimolar
  d.radius = std::sqrt(area / std::numbers::pi);
  return d;
}

}  // namespace

TEST(DbmLaplaceSlow, DropletPressureJumpIsSigmaOverR) {
  const materials::VanDerWaals vdw;
  const Coexistence co = maxwell_construction(vdw, kT);
  const Flat flat = flat_interface_tension(co);
  const double sigma = flat.sigma, sigma_theory = interface_tension(vdw, flat.T, kK);
  std::printf("sigma: flat profile K*int(rho')^2 = %.6f, square-gradient integral at the slab's mean T = %.5f: "
              "%.6f (at T = 0.9: %.6f)\n",
              sigma, flat.T, sigma_theory, interface_tension(vdw, kT, kK));
  EXPECT_NEAR(sigma / sigma_theory, 1.0, 0.10);
  std::vector<double> dpR;
  for (double r0 : {0.45, 0.6, 0.75}) {
    const Droplet d = run_droplet(r0, co, vdw);
    std::printf("R0 = %.2f  R = %.4f  dp = %.6f  sigma/R = %.6f  dp*R/sigma = %.4f  max|u| = %.3g\n", r0,
                d.radius, d.dp, sigma / d.radius, d.dp * d.radius / sigma, d.spurious);
    EXPECT_NEAR(d.dp * d.radius / sigma, 1.0, 0.10) << "R0 = " << r0;
    dpR.push_back(d.dp * d.radius);
  }
  const auto [lo, hi] = std::minmax_element(dpR.begin(), dpR.end());
  EXPECT_LT((*hi - *lo) / sigma, 0.10);
}
