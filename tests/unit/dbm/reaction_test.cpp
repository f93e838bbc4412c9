// Reactive DBM (reaction.hpp): the chemical source against its definition and against the
// homogeneous-reactor ODE, conservation of E + Qφ (Xu et al. 2015, §2.3.3; Yan et al. 2013), and the
// reactant transport's consistency with the DBM mass flux.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/reaction.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

const VelocityModel kModel = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);

Lattice box(int nx, int ny, double dx) {
  Lattice l;
  l.nx = nx, l.ny = ny, l.dx = l.dy = dx;
  return l;
}

Boundaries periodic() { return Boundaries{}; }

// Δt at Courant number 0.4 and τ = 2Δt (well inside the RK3 limit Δt/τ < 2.5).
BgkSettings settings(const Lattice& l) {
  BgkSettings s;
  s.dt = 0.4 * l.dx / kModel.max_speed();
  s.tau = 2.0 * s.dt;
  return s;
}

// dλ/dt = −ω(λ, ρ, T) with T = T0 + (2Q/b)(λ0 − λ) (closed box: the heat goes into T at fixed
// ρ, u = 0), by classical RK4 with a step far below the DBM's.
double reactor_ode(const RateLaw& law, double rho, double T0, double b, double t_end) {
  const double lambda0 = 1.0;
  auto rate = [&](double lambda) {
    const double T = T0 + 2.0 * law.heat_release * (lambda0 - lambda) / b;
    return -law.consumption(lambda, rho, T);
  };
  const int n = 200000;
  const double h = t_end / n;
  double y = lambda0;
  for (int s = 0; s < n; ++s) {
    const double k1 = rate(y), k2 = rate(y + 0.5 * h * k1), k3 = rate(y + 0.5 * h * k2), k4 = rate(y + h * k3);
    y += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0;
  }
  return y;
}

// A homogeneous periodic box reacting from λ = 1: λ(t) and T(t) against the ODE.
void check_homogeneous(const RateLaw& law, double rho, double T0, double t_end) {
  const Lattice l = box(4, 4, 0.05);
  Simulation sim(kModel, l, periodic(), settings(l));
  ReactiveFlow flow(sim, periodic(), law);
  sim.initialize([&](double, double) { return Macro{rho, 0.0, 0.0, T0}; });
  flow.initialize([](double, double) { return 1.0; });
  const long long steps = std::llround(t_end / sim.settings().dt);
  for (long long s = 0; s < steps; ++s) sim.step();
  const double lambda = reactor_ode(law, rho, T0, sim.b(), sim.time());
  const double T = T0 + 2.0 * law.heat_release * (1.0 - lambda) / sim.b();
  EXPECT_GT(1.0 - lambda, 0.5) << "the reaction should have progressed far";
  EXPECT_NEAR(flow.lambda(2, 1), lambda, 1e-6);
  EXPECT_NEAR(sim.macro(2, 1).T, T, 1e-6);
  EXPECT_NEAR(sim.macro(2, 1).rho, rho, 1e-12);
  EXPECT_NEAR(sim.macro(2, 1).ux, 0.0, 1e-12);
}

// Density, velocity and temperature bumps in a periodic 2D box.
Macro blob(double x, double y) {
  const double r2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
  const double g = std::exp(-r2 / 0.02);
  return {1.0 + 0.3 * g, 0.2 + 0.2 * g * (y - 0.5), -0.2 * g * (x - 0.5), 0.8 + 0.2 * g};
}

}  // namespace

TEST(DbmReaction, TemperatureDerivativeOfEquilibriumMoments) {
  // M^eq is quadratic in T, so the central difference is exact up to round-off.
  for (double b : {2.0, 5.0}) {
    const double rho = 1.3, ux = 0.4, uy = -0.7, T = 0.9, h = 1e-3;
    const auto fd = ((equilibrium_moments(rho, ux, uy, T + h, b) -
                      equilibrium_moments(rho, ux, uy, T - h, b)) / (2 * h)).eval();
    const auto exact = equilibrium_moments_dT(rho, ux, uy, T, b);
    for (int q = 0; q < kMoments; ++q) EXPECT_NEAR(exact[q], fd[q], 1e-10) << "moment " << q;
  }
}

TEST(DbmReaction, RateLaws) {
  RateLaw a;
  a.rate = 3.0, a.activation = 2.0, a.ignition_temperature = 0.5;
  EXPECT_DOUBLE_EQ(a.consumption(0.4, 2.0, 0.8), 3.0 * 0.4 * std::exp(-2.0 / 0.8));
  EXPECT_EQ(a.consumption(0.4, 2.0, 0.49), 0.0);
  RateLaw c;
  c.kind = RateKind::cochran;
  c.omega1 = 2.0, c.omega2 = 5.0, c.m = 1.5, c.n = 0.5;
  const double p = 2.0 * 0.8;
  EXPECT_DOUBLE_EQ(c.consumption(0.4, 2.0, 0.8),
                   2.0 * std::pow(p, 1.5) * 0.4 + 5.0 * std::sqrt(p) * 0.4 * 0.6);
}

TEST(DbmReaction, HomogeneousFirstOrderMatchesExponential) {
  // E_a = 0: ω = kλ, λ = exp(−kt) whatever the temperature.
  RateLaw law;
  law.rate = 2.0, law.heat_release = 0.5;
  const Lattice l = box(2, 2, 0.05);
  Simulation sim(kModel, l, periodic(), settings(l));
  ReactiveFlow flow(sim, periodic(), law);
  sim.initialize([](double, double) { return Macro{1.0, 0.0, 0.0, 0.6}; });
  flow.initialize([](double, double) { return 1.0; });
  while (sim.time() < 0.5) sim.step();
  EXPECT_NEAR(flow.lambda(0, 0), std::exp(-2.0 * sim.time()), 1e-7);
}

TEST(DbmReaction, HomogeneousArrheniusMatchesOde) {
  RateLaw law;
  law.rate = 20.0, law.activation = 2.0, law.heat_release = 0.6, law.ignition_temperature = 0.5;
  check_homogeneous(law, 1.2, 0.7, 0.6);
}

TEST(DbmReaction, HomogeneousCochranMatchesOde) {
  RateLaw law;
  law.kind = RateKind::cochran;
  law.omega1 = 1.0, law.omega2 = 6.0, law.m = 1.0, law.n = 2.0, law.heat_release = 0.4;
  check_homogeneous(law, 1.0, 0.7, 0.5);
}

TEST(DbmReaction, ConservesMassMomentumAndTotalEnergyInPeriodicBox) {
  const Lattice l = box(24, 24, 1.0 / 24);
  Simulation sim(kModel, l, periodic(), settings(l));
  RateLaw law;
  law.rate = 5.0, law.heat_release = 0.3, law.ignition_temperature = 0.85;  // burns in the blob
  ReactiveFlow flow(sim, periodic(), law);
  sim.initialize(blob);
  flow.initialize([](double x, double) { return 0.5 + 0.4 * std::sin(2 * M_PI * x); });
  const auto before = sim.totals();
  const double chem_before = flow.chemical_energy();
  for (int s = 0; s < 150; ++s) sim.step();
  sim.check_state();
  const auto after = sim.totals();
  const double chem_after = flow.chemical_energy();
  EXPECT_LT(chem_after, 0.97 * chem_before) << "the blob should have burnt some reactant";
  EXPECT_GT(after[3], before[3] + 0.5 * (chem_before - chem_after));
  EXPECT_NEAR(after[0], before[0], 1e-12 * before[0]);
  EXPECT_NEAR(after[1], before[1], 1e-12);
  EXPECT_NEAR(after[2], before[2], 1e-12);
  EXPECT_NEAR(after[3] + chem_after, before[3] + chem_before, 1e-12 * (before[3] + chem_before));
}

TEST(DbmReaction, UniformReactantStaysUniformInAFlow) {
  // No reaction (T_ign above every T): φ = ρλ must follow ρ exactly when λ is uniform, since the
  // reactant rides on the DBM's own face mass fluxes.
  const Lattice l = box(24, 24, 1.0 / 24);
  Simulation sim(kModel, l, periodic(), settings(l));
  RateLaw law;
  law.ignition_temperature = 10.0;
  ReactiveFlow flow(sim, periodic(), law);
  sim.initialize(blob);
  flow.initialize([](double, double) { return 0.37; });
  for (int s = 0; s < 100; ++s) sim.step();
  sim.check_state();
  double worst = 0.0;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) worst = std::max(worst, std::abs(flow.lambda(i, j) - 0.37));
  EXPECT_LT(worst, 1e-13);
}

TEST(DbmReaction, RefusesSpectralConvectionAndNonPositiveHeat) {
  const Lattice l = box(8, 8, 1.0 / 8);
  BgkSettings s = settings(l);
  s.spectral_convection = true;
  Simulation spectral(kModel, l, periodic(), s);
  EXPECT_THROW(ReactiveFlow(spectral, periodic(), RateLaw{}), InputError);
  Simulation sim(kModel, l, periodic(), settings(l));
  RateLaw law;
  law.heat_release = 0.0;
  EXPECT_THROW(ReactiveFlow(sim, periodic(), law), InputError);
}
