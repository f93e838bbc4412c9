// Phase-separation diagnostics of the GLS model (Xu et al. 2015, §4.3): the quench initial state, one
// sample of D, L, R against quantities computed here independently, and t_SD / D_max from the
// peak of D(t). The long K study is not a unit test (see docs/theory/dbm.md for its status).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/dbm/phase_separation.hpp"
#include "unit/dbm_gls/gls_setup.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

TEST(DbmPhaseSeparation, QuenchIsSeededNoiseAroundTheMeanDensity) {
  Lattice lattice;
  lattice.nx = lattice.ny = 32, lattice.dx = lattice.dy = 1.0 / 32;
  Quench q;
  q.noise = 0.05;
  double mean = 0, lo = 1e9, hi = -1e9;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const Macro m = q.state(lattice, lattice.x(i), lattice.y(j));
      EXPECT_EQ(m.rho, q.state(lattice, lattice.x(i), lattice.y(j)).rho);
      mean += m.rho / 1024, lo = std::min(lo, m.rho), hi = std::max(hi, m.rho);
    }
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_GE(lo, 0.95);
  EXPECT_LE(hi, 1.05);
  Quench other = q;
  other.seed = 2;
  EXPECT_NE(other.state(lattice, 0.5, 0.5).rho, q.state(lattice, 0.5, 0.5).rho);
}

TEST(DbmPhaseSeparation, SampleOfAStripe) {
  // ρ = 1 + 0.3 sin(2πx): two straight boundaries of length 1 at ρ = 1 (L = 2), R = 2π/k₁ = 1,
  // no TNE in the initial equilibrium state, the variance 0.3²/2.
  gls_testing::GlsCase c;
  c.nx = c.ny = 32, c.K = 1e-3, c.tau = 1e-3, c.dt = 2e-4;
  auto run = gls_testing::make_gls(c, [](double x, double) {
    return Macro{1.0 + 0.3 * std::sin(2 * std::numbers::pi * x), 0, 0, 0.9};
  });
  const PhaseSample s = sample_phase_separation(*run.sim, *run.force, 1.0);
  EXPECT_NEAR(s.boundary_length, 2.0, 0.12);  // lattice-line estimate: axis-aligned lines 5% short
  EXPECT_NEAR(s.domain_size, 1.0, 1e-9);
  EXPECT_NEAR(s.density_variance, 0.045, 1e-9);
  EXPECT_NEAR(s.D, 0.0, 1e-12);
  EXPECT_NEAR(s.mass, 1.0, 1e-12);
  for (int k = 0; k < 5; ++k) run.sim->step();
  const PhaseSample later = sample_phase_separation(*run.sim, *run.force, 1.0);
  EXPECT_GT(later.D, 1e-6);  // the force drives the state off equilibrium
  EXPECT_LE(later.D, later.D_force + later.D_gradient + 1e-15);  // triangle inequality (eq. 30)
}

TEST(DbmPhaseSeparation, SpinodalEndIsThePeakOfD) {
  std::vector<PhaseSample> samples;
  for (int i = 0; i <= 20; ++i) {
    PhaseSample s;
    s.t = 0.1 * i;
    s.D = std::exp(-std::pow(s.t - 1.2, 2));
    s.boundary_length = 5 - std::abs(s.t - 1.1);
    samples.push_back(s);
  }
  const SpinodalEnd e = spinodal_end(samples);
  EXPECT_NEAR(e.t_sd, 1.2, 1e-12);
  EXPECT_NEAR(e.D_max, 1.0, 1e-12);
  EXPECT_NEAR(e.t_L_max, 1.1, 1e-12);
  EXPECT_NEAR(e.L_max, 5.0, 1e-12);
}
