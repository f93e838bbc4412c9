// TNE measures (seed eqs. 27, 35) against their Chapman–Enskog values in a smooth flow: for the
// BGK model with b = 2/(γ−1) degrees of freedom,
//   Δ*_2,xy   = −μ (∂_x u_y + ∂_y u_x),  μ = τ ρ T,
//   Δ*_(3,1)  = q = −κ ∇T,               κ = (b+2)/2 · τ ρ T (Pr = 1).
// Flow: shear wave u_x = A sin 2πy and an isobaric temperature wave T = 1 + δ sin 2πx on a
// periodic 64² lattice, measured after ~25 τ (the first-order Chapman–Enskog state is reached
// after a few τ). Tolerance 3% in the L2 norm: the neglected O(τ k c) terms are ~1% and the
// central differences used for the reference gradients ~0.3%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "shockfield/dbm/simulation.hpp"
#include "shockfield/dbm/tne.hpp"

using namespace shockfield::dbm;

TEST(DbmTne, CentralMeasuresMatchChapmanEnskog) {
  const double two_pi = 2.0 * std::numbers::pi, A = 0.05, delta = 0.05;
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = l.ny = 64;
  l.dx = l.dy = 1.0 / 64;
  BgkSettings s;
  s.dt = 0.4 * l.dx / model.max_speed();
  s.tau = 2e-3;
  Simulation sim(model, l, Boundaries{}, s);
  sim.initialize([&](double x, double y) {
    const double T = 1.0 + delta * std::sin(two_pi * x);
    return Macro{1.0 / T, A * std::sin(two_pi * y), 0.0, T};
  });
  for (int n = 0; n < 32; ++n) sim.step();
  const TneFields tne = tne_measures(sim);

  const double b = sim.b();
  double err2 = 0, ref2 = 0, errq = 0, refq = 0;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = sim.macro(i, j);
      const auto wrap = [](int a, int n) { return (a + n) % n; };
      const Macro xp = sim.macro(wrap(i + 1, l.nx), j), xm = sim.macro(wrap(i - 1, l.nx), j);
      const Macro yp = sim.macro(i, wrap(j + 1, l.ny)), ym = sim.macro(i, wrap(j - 1, l.ny));
      const double dux_dy = (yp.ux - ym.ux) / (2 * l.dy), duy_dx = (xp.uy - xm.uy) / (2 * l.dx);
      const double dT_dx = (xp.T - xm.T) / (2 * l.dx);
      const double p = m.rho * m.T;
      const double stress = -s.tau * p * (dux_dy + duy_dx);
      const double heat = -(b + 2) / 2 * s.tau * p * dT_dx;
      const std::size_t id = i + static_cast<std::size_t>(l.nx) * j;
      err2 += std::pow(tne.central[1][id] - stress, 2);
      ref2 += stress * stress;
      errq += std::pow(tne.central[7][id] - heat, 2);
      refq += heat * heat;
    }
  std::printf("relative L2 error: Delta*_2xy %.4f, Delta*_(3,1)x %.4f\n", std::sqrt(err2 / ref2),
              std::sqrt(errq / refq));
  EXPECT_LT(std::sqrt(err2 / ref2), 0.03);
  EXPECT_LT(std::sqrt(errq / refq), 0.03);
  // D (eq. 35) is positive out of equilibrium and the averages are the field means.
  EXPECT_GT(tne.mean_strength, 0.0);
  double sum = 0;
  for (double v : tne.central[1]) sum += v;
  EXPECT_NEAR(tne.mean_central[1], sum / (l.nx * l.ny), 1e-15);
}

TEST(DbmTne, EquilibriumHasNoNonEquilibrium) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = l.ny = 4;
  BgkSettings s;
  s.dt = 0.1;
  s.tau = 0.1;
  Simulation sim(model, l, Boundaries{}, s);
  sim.initialize([](double, double) { return Macro{1.2, 0.3, -0.1, 0.9}; });
  const TneFields tne = tne_measures(sim);
  for (int q = 0; q < kTneComponents; ++q) {
    EXPECT_NEAR(tne.mean_raw[q], 0.0, 1e-13) << kTneNames[q];
    EXPECT_NEAR(tne.mean_central[q], 0.0, 1e-13) << kTneNames[q];
  }
  EXPECT_NEAR(tne.mean_strength, 0.0, 1e-13);
}
