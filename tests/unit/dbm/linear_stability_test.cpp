// Von Neumann analysis of the BGK DBM about a uniform state (linear_stability.hpp): the collision
// Jacobian against finite differences, the conserved modes at k = 0, and the predicted growth
// against direct simulations of a perturbed uniform gas (docs/theory/dbm.md, "Linear stability").
#include "shockfield/dbm/linear_stability.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "shockfield/dbm/detonation_theory.hpp"
#include "shockfield/dbm/simulation.hpp"

namespace shockfield::dbm {
namespace {

constexpr double kB = 5.0;  // γ = 1.4

// The detonation set-up of docs/theory/dbm.md ("Stability window"): speeds 1..4, η0 = 2, τ = 2e-3,
// Δx = 0.01, Δt = 1e-3, one cell high.
StabilityProblem detonation_problem() {
  StabilityProblem p;
  p.model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  p.b = kB, p.tau = 2e-3, p.dt = 1e-3, p.dx = p.dy = 0.01;
  p.two_dimensional = false;
  return p;
}

TEST(DbmLinearStability, EquilibriumJacobianMatchesFiniteDifferences) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const MomentInversion inversion(model);
  const Macro state{0.9, 0.3, -0.2, 1.1};
  const RealMatrix16 jacobian = equilibrium_jacobian(model, inversion, state, kB);
  double f[kMoments];
  inversion.equilibrium(state.rho, state.ux, state.uy, state.T, kB, f);
  const auto feq_of = [&](const double* g, double* out) {
    const Macro m = macro_of(model, g, 1, kB);
    inversion.equilibrium(m.rho, m.ux, m.uy, m.T, kB, out);
  };
  const double h = 1e-6;
  double worst = 0.0;
  for (int j = 0; j < kMoments; ++j) {
    double plus[kMoments], minus[kMoments], g[kMoments];
    std::copy(f, f + kMoments, g);
    g[j] += h;
    feq_of(g, plus);
    g[j] -= 2.0 * h;
    feq_of(g, minus);
    for (int i = 0; i < kMoments; ++i)
      worst = std::max(worst, std::abs((plus[i] - minus[i]) / (2.0 * h) - jacobian(i, j)));
  }
  EXPECT_LT(worst, 1e-7 * jacobian.cwiseAbs().maxCoeff());
  // A projection onto the equilibria: (∂f^eq/∂f)² = ∂f^eq/∂f.
  EXPECT_LT((jacobian * jacobian - jacobian).cwiseAbs().maxCoeff(), 1e-10 * jacobian.cwiseAbs().maxCoeff());
}

TEST(DbmLinearStability, ZeroWaveVectorKeepsMassMomentumAndEnergy) {
  StabilityProblem p = detonation_problem();
  p.dt = 1.5e-3;
  const RealMatrix16 J = collision_jacobian(p, {1.0, 0.2, -0.1, 0.8});
  // ρ, ρu, E are left null vectors of J: collisions conserve them.
  for (int m = 0; m < 4; ++m) {
    Eigen::Matrix<double, 1, kMoments> w;
    for (int k = 0; k < kMoments; ++k) w(k) = moment_row(p.model.vx[k], p.model.vy[k], p.model.eta[k])(m);
    EXPECT_LT((w * J).cwiseAbs().maxCoeff(), 1e-12 / p.tau) << "moment " << m;
  }
  const ComplexMatrix16 A = step_matrix(p, J, 0.0, 0.0, p.stencil);
  const ComplexMatrix16 G = ComplexMatrix16::Identity() + A + A * A / 2.0 + A * A * A / 6.0;
  int ones = 0, relaxed = 0;
  const std::complex<double> fast = rk3_factor(-p.dt / p.tau);
  const Eigen::ComplexEigenSolver<ComplexMatrix16> solver(G, false);
  for (const auto g : solver.eigenvalues()) {
    ones += std::abs(g - 1.0) < 1e-12;
    relaxed += std::abs(g - fast) < 1e-12;
  }
  EXPECT_EQ(ones, 4);  // mass, two momenta, energy
  EXPECT_EQ(relaxed, 12);
}

TEST(DbmLinearStability, ConvectionSymbolsAreConsistent) {
  // Every stencil approximates i v k at small θ: to O(θ) (first order) or O(θ²).
  for (const Stencil s : {Stencil::second_order_upwind, Stencil::central, Stencil::first_order_upwind})
    for (const double v : {2.0, -3.0}) {
      const double theta = 1e-3, h = 0.5;
      const std::complex<double> exact(0.0, v * theta / h);
      const double order = s == Stencil::first_order_upwind ? 1.0 : 2.0;
      EXPECT_LT(std::abs(convection_symbol(v, theta, h, s) - exact), 2.0 * std::abs(v) / h * std::pow(theta, order + 1))
          << stencil_name(s);
      if (s != Stencil::central) {
        EXPECT_GT(convection_symbol(v, 2.0, h, s).real(), 0.0);  // upwind damps
      }
    }
}

enum class Seed { odd_even, smooth };

// Growth rate of the L2 norm of f − f^eq(state) in a periodic 64 × 1 (2D: 16 × 16) lattice,
// fitted over the second half of the run (at most its last 0.3 time units), which ends at t_end
// or when the norm reaches 1e-4 (1e-3 with the smooth seed; still linear). Seeds: a 1e-9 odd–even (checkerboard)
// perturbation of every f_k (the mode NND convects exactly like first-order upwind: every minmod
// slope is zero), or a smooth u_y = 1e-6 sin(2πx/L) with round-off seeding the rest (the
// experiment of docs/theory/dbm.md, "Stability window"). `overall`: the norm at the end over
// the paper's.
double measured_growth_rate(const StabilityProblem& p, const Macro& s, double t_end, double* overall = nullptr,
                            Seed seed = Seed::odd_even) {
  Lattice lattice;
  lattice.nx = p.two_dimensional ? 16 : 64, lattice.ny = p.two_dimensional ? 16 : 1;
  lattice.dx = lattice.dy = p.dx;
  BgkSettings settings;
  settings.gamma = 1.0 + 2.0 / p.b, settings.tau = p.tau, settings.dt = p.dt;
  Simulation sim(p.model, lattice, Boundaries{}, settings);
  const double length = lattice.nx * p.dx;
  sim.initialize([&](double x, double) {
    Macro m = s;
    if (seed == Seed::smooth) m.uy += 1e-6 * std::sin(2.0 * std::numbers::pi * x / length);
    return m;
  });
  double f0[kMoments];
  sim.inversion().equilibrium(s.rho, s.ux, s.uy, s.T, p.b, f0);
  const std::size_t N = lattice.cells();
  for (int k = 0; seed == Seed::odd_even && k < kMoments; ++k)
    for (int j = 0; j < lattice.ny; ++j)
      for (int i = 0; i < lattice.nx; ++i)
        sim.f()[k * N + lattice.at(i, j)] += 1e-9 * ((i + j) % 2 == 0 ? 1.0 : -1.0) * std::cos(1.7 * k);
  const auto norm = [&] {
    double sum = 0.0;
    for (int k = 0; k < kMoments; ++k)
      for (int j = 0; j < lattice.ny; ++j)
        for (int i = 0; i < lattice.nx; ++i) sum += std::pow(sim.f()[k * N + lattice.at(i, j)] - f0[k], 2);
    return std::sqrt(sum);
  };
  std::vector<double> history{norm()};
  const double stop = seed == Seed::smooth ? 1e-3 : 1e-4;  // the smooth seed's norm is ~1e-5
  while (sim.time() < t_end && history.back() < stop) {
    sim.step();
    history.push_back(norm());
  }
  const std::size_t n = history.size() - 1;
  if (overall) *overall = history[n] / history[0];
  const std::size_t first = n - std::min(n / 2, static_cast<std::size_t>(std::round(0.3 / p.dt)));
  return std::log(history[n] / history[first]) / ((n - first) * p.dt);
}

TEST(DbmLinearStability, GrowthAtRestMatchesDirectSimulation) {
  // docs/theory/dbm.md: speeds 1..4, η0 = 2 are stable at T = 1.0 and unstable at T = 1.35
  // (≈ 10 per unit time); ρ = 0.92, u = 0.
  const StabilityProblem p = detonation_problem();
  const StabilityReport cold = analyse_stability(p, {0.92, 0.0, 0.0, 1.0});
  EXPECT_LT(cold.semi_discrete_rate, tolerance_rate(p.tau));
  EXPECT_LT(cold.discrete_rate, tolerance_rate(p.tau));
  EXPECT_LT(cold.model_rate, 0.0);
  EXPECT_GT(cold.stable_dt, p.dt);
  double overall = 0.0;
  const double decay = measured_growth_rate(p, {0.92, 0.0, 0.0, 1.0}, 0.5, &overall);
  EXPECT_LT(decay, 0.0);
  EXPECT_LT(overall, 1e-3);
  RecordProperty("measured_rate_T1.0", fmt::format("{}", decay));
  for (const double T : {1.3, 1.35, 1.5}) {
    const StabilityReport hot = analyse_stability(p, {0.92, 0.0, 0.0, T});
    EXPECT_GT(hot.semi_discrete_rate, 1.0);  // no time step helps
    EXPECT_NEAR(hot.discrete_rate, hot.semi_discrete_rate, 0.05 * hot.semi_discrete_rate);
    EXPECT_DOUBLE_EQ(hot.theta_x, std::numbers::pi);  // the odd–even mode
    EXPECT_GT(hot.model_rate, 0.0);                  // the BGK model itself (short waves)
    const double measured = measured_growth_rate(p, {0.92, 0.0, 0.0, T}, 2.5);
    EXPECT_NEAR(measured, hot.discrete_rate, 0.2 * hot.discrete_rate) << "T = " << T;
    RecordProperty(fmt::format("T{}", T), fmt::format("{} measured, {} predicted", measured, hot.discrete_rate));
    // The documented experiment, T = 1.35 with a smooth seed: the odd–even mode grows out of
    // round-off (at T = 1.3 it needs longer to outgrow the paper; at 1.5 the last 0.3 time units
    // still include its emergence).
    if (T != 1.35) continue;
    const double smooth = measured_growth_rate(p, {0.92, 0.0, 0.0, T}, 4.0, nullptr, Seed::smooth);
    EXPECT_NEAR(smooth, hot.discrete_rate, 0.2 * hot.discrete_rate) << "T = " << T;
    RecordProperty(fmt::format("smooth_T{}", T), fmt::format("{} measured", smooth));
  }
}

TEST(DbmLinearStability, UnlimitedSecondOrderUpwindIsNotWhatNndDoes) {
  // At T = 1.25 the unlimited second-order upwind stencil predicts growth ≈ 9.2 per unit time
  // (at high θ, where minmod clips the slopes), the first-order one decay; the NND run decays.
  StabilityProblem p = detonation_problem();
  const Macro state{0.92, 0.0, 0.0, 1.25};
  EXPECT_LT(analyse_stability(p, state).discrete_rate, tolerance_rate(p.tau));
  EXPECT_LT(analyse_stability(p, state).smooth_rate, tolerance_rate(p.tau));  // its growth is not smooth
  p.stencil = Stencil::second_order_upwind;
  const double unlimited = analyse_stability(p, state).semi_discrete_rate;
  EXPECT_NEAR(unlimited, 9.2, 0.1);
  double overall = 0.0;
  const double measured = measured_growth_rate(p, state, 4.0, &overall, Seed::smooth);
  EXPECT_LT(measured, 0.0);
  EXPECT_LT(overall, 1.0);
}

TEST(DbmLinearStability, SmoothModesOfTheMovingVonNeumannState) {
  // The von Neumann state of examples/dbm_detonation (ρ0 = 1, p0 = 0.6, Q = 0.6) moving at u_vN:
  // the BGK model is unstable there, first-order upwind damps every mode at τ = 2e-3 down to
  // Δx = 0.0025, but the second-order upwind stencil NND uses on smooth modes lets kΔx ≈ 0.47
  // grow at Δx = 0.0025, barely at 0.005 (docs/theory/dbm.md, "Smooth modes"). A periodic NND run
  // (smooth seed, round-off) grows at 3.8 per unit time at Δx = 0.0025 — the limiter clips part of
  // the second-order stencil's 10.4 — and decays at Δx = 0.005.
  const GasState vn = chapman_jouguet({1.0, 0.0, 0.6}, 1.4, 0.6).von_neumann;
  const Macro state{vn.rho, vn.u, 0.0, vn.p / vn.rho};
  StabilityProblem p = detonation_problem();
  std::vector<double> measured;
  for (const double dx : {0.0025, 0.005}) {
    p.dx = p.dy = dx, p.dt = 0.4 * dx / 4.0;  // courant = 0.4
    const StabilityReport r = analyse_stability(p, state);
    EXPECT_NEAR(r.model_rate, 16.8, 0.1);
    EXPECT_LT(r.discrete_rate, tolerance_rate(p.tau)) << "dx = " << dx;  // what the check saw before
    EXPECT_LT(r.smooth_theta_x, kSmoothTheta);
    if (dx == 0.0025) {
      EXPECT_NEAR(r.smooth_rate, 10.4, 0.1);
    } else {
      EXPECT_NEAR(r.smooth_rate, 0.27, 0.01);
    }
    double overall = 0.0;
    measured.push_back(measured_growth_rate(p, state, 8.0, &overall, Seed::smooth));
    const std::string result =
        fmt::format("{} measured (growth {} overall), {} predicted smooth", measured.back(), overall, r.smooth_rate);
    std::printf("dx = %g: %s\n", dx, result.c_str());
    RecordProperty(fmt::format("dx{}", dx), result);
  }
  EXPECT_GT(measured[0], 3.0);
  EXPECT_LT(measured[0], 10.4);
  EXPECT_LT(measured[1], 0.0);
}

TEST(DbmLinearStability, LaxSpeedsStableOverTheLaxTemperatures) {
  // The Lax tube (shock_tube_test.cpp): speeds (3, 2, 5, 10), η0 = 8, 400 cells on [0, 1],
  // τ = Δt = 0.4Δx/10; T from 1.1 (right) to 7.9 (left), |u| up to 1.53 (star region).
  StabilityProblem p;
  p.model = d2v16({3.0, 2.0, 5.0, 10.0}, 8.0);
  p.b = kB, p.dx = p.dy = 1.0 / 400, p.dt = p.tau = 0.4 * p.dx / 10.0;
  p.two_dimensional = false;
  for (double T = 1.1; T <= 7.9 + 1e-9; T += 0.4)
    for (const double u : {0.0, 1.5}) {
      const StabilityReport r = analyse_stability(p, {1.0, u, 0.0, T});
      EXPECT_LT(r.model_rate, tolerance_rate(p.tau)) << "T = " << T << ", u = " << u;
      EXPECT_LT(r.discrete_rate, tolerance_rate(p.tau)) << "T = " << T << ", u = " << u;
    }
  // ... where speeds 1..4 are not.
  p.model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  p.dt = p.tau = 0.4 * p.dx / 4.0;
  EXPECT_GT(analyse_stability(p, {1.0, 0.0, 0.0, 7.9}).discrete_rate, 1.0);
}

TEST(DbmLinearStability, LargestStableTimeStep) {
  // The relaxation alone limits Δt/τ to the RK3 bound 2.51 on the negative real axis; with
  // convection on a 2D lattice the first-order upwind limit is lower. Just below stable_dt a
  // perturbed NND run decays, just above it grows at the predicted rate.
  StabilityProblem p = detonation_problem();
  p.two_dimensional = true;
  p.resolution = 16;
  const Macro state{1.0, 0.0, 0.0, 1.0};
  const double limit = analyse_stability(p, state).stable_dt;
  EXPECT_LT(limit, 2.52 * p.tau);
  for (const double factor : {0.98, 1.05}) {
    p.dt = factor * limit;
    const StabilityReport r = analyse_stability(p, state);
    double overall = 0.0;
    const double measured = measured_growth_rate(p, state, 0.5, &overall);
    RecordProperty(fmt::format("dt_factor{}", factor), fmt::format("{} measured, {} predicted", measured, r.discrete_rate));
    if (factor < 1.0) {
      EXPECT_LT(r.discrete_rate, tolerance_rate(p.tau));
      EXPECT_LT(overall, 1e-3);
    } else {
      EXPECT_GT(r.discrete_rate, 1.0);
      EXPECT_NEAR(measured, r.discrete_rate, 0.2 * r.discrete_rate);
    }
  }
}

}  // namespace
}  // namespace shockfield::dbm
