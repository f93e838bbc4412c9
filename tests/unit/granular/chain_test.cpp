// The chain model: Hertz's κ, the static equilibrium under gravity, refused chains and steps,
// and energy conservation of the velocity-Verlet loop.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/chain.hpp"
#include "shockfield/granular/contact_loop.hpp"
#include "shockfield/granular/nesterenko.hpp"
#include "shockfield/granular/simulation.hpp"

namespace shockfield::granular {
namespace {

// Steel spheres of R = 2 mm on a rigid floor under gravity, with a mass, a radius, a modulus
// and a modulus-and-Poisson-ratio impurity.
ChainSpec steel_column(long long n) {
  return {.grains = n, .radius = 2e-3, .gravity = 9.81, .wall = WallKind::rigid,
          .impurities = {{10, 0.3, 1.0, 1.0, {}}, {20, 1.0, 1.7, 1.0, {}}, {30, 1.0, 1.0, 4.0, {}}, {35, 1.0, 1.0, 0.5, 0.45}}};
}

// Touching steel spheres on a horizontal line, no wall.
ChainSpec horizontal(long long n, double radius) {
  ChainSpec s;
  s.grains = n;
  s.radius = radius;
  return s;
}

TEST(GranularChain, HertzKappaMatchesTheClosedFormsForEqualSpheresAndAFlatWall) {
  // Equal spheres: E* = E/(2(1-ν²)), R* = R/2; sphere on a rigid flat: E* = E/(1-ν²), R* = R.
  const double E = 200e9, nu = 0.3, R = 2e-3, inf = INFINITY;
  const ChainSpec s = steel_column(40);
  const Chain c = build_chain(s);
  const double pair = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(R / 2);
  const double wall = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R);
  EXPECT_NEAR(c.kappa[0] / pair, 1.0, 1e-14);
  EXPECT_NEAR(c.wall_kappa / wall, 1.0, 1e-14);
  EXPECT_NEAR(hertz_kappa(E, nu, R, inf, 0.0, inf) / wall, 1.0, 1e-14);
  // The modulus impurity at 30: 1/E* = (1-ν²)(1/E + 1/4E), on both of its contacts.
  EXPECT_NEAR(c.kappa[30] / (4.0 / 3.0 / ((1 - nu * nu) * 1.25 / E) * std::sqrt(R / 2)), 1.0, 1e-14);
  EXPECT_EQ(c.kappa[29], c.kappa[30]);
  // The impurity at 35 with E/2 and its own ν = 0.45: 1/E* = (1-0.3²)/E + (1-0.45²)/(E/2)
  // (= 2.505/E, against 2.73/E with the chain's ν: κ 9% higher, so a ν that were ignored fails).
  const double own = 4.0 / 3.0 / ((1 - nu * nu) / E + (1 - 0.45 * 0.45) / (0.5 * E)) * std::sqrt(R / 2);
  EXPECT_NEAR(c.kappa[34] / own, 1.0, 1e-14);
  EXPECT_NEAR(c.kappa[35] / own, 1.0, 1e-14);
  EXPECT_NEAR(c.kappa[36] / pair, 1.0, 1e-14);
  // The same grain last, on the rigid floor: E* = (E/2)/(1-0.45²).
  ChainSpec last = steel_column(36);
  const Chain d = build_chain(last);
  EXPECT_NEAR(d.wall_kappa / (4.0 / 3.0 * 0.5 * E / (1 - 0.45 * 0.45) * std::sqrt(R)), 1.0, 1e-14);
}

TEST(GranularChain, StaticEquilibriumUnderGravityBalancesEveryGrainToRoundOff) {
  const Chain c = build_chain(steel_column(2000));
  double weight = 0;
  for (double m : c.mass) weight += m * c.gravity;
  Simulation sim(c, Impulse{Impulse::Kind::velocity, 0.0, 1, {}, {}}, 1e-7);
  // Each F_k = κ_k δ_k^{3/2} carries W_k to a few ulps, so f_i = F_{i-1} - F_i + m_i g is
  // round-off of the total weight: |f_i| <= 1e-14 W (a few eps of the largest force).
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_LE(std::abs(sim.force()[i]), 1e-14 * weight) << i;
  EXPECT_NEAR(sim.wall_force() / weight, 1.0, 1e-14);
  for (int s = 0; s < 200; ++s) sim.step();
  double vmax = 0;
  for (double v : sim.velocity()) vmax = std::max(vmax, std::abs(v));
  // Round-off forces of 1e-14 W accelerate a grain by < 1e-14·2000 g: after 200 steps of 1e-7 s
  // its speed is < 1e-14·2000·9.81·2e-5 ≈ 4e-15 m/s.
  EXPECT_LT(vmax, 1e-14);
}

TEST(GranularChain, RefusesChainsThatAreNotChains) {
  // A 40-grain column (its impurities inside) with one thing wrong at a time; each message is
  // checked so that a chain refused for another reason fails the test.
  const auto refused = [](const ChainSpec& s, const std::string& said) {
    try {
      build_chain(s);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(said), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted; expected: " << said;
  };
  EXPECT_NO_THROW(build_chain(steel_column(40)));
  ChainSpec s = steel_column(40);
  s.radius = 0;
  refused(s, "radius");
  s = steel_column(40);
  s.impurities = {{40, 0.5, 1, 1, {}}};
  refused(s, "outside the chain");
  s.impurities = {{3, 1, -1, 1, {}}};
  refused(s, "ratios must be positive");
  s.impurities = {{3, 1, 1, 1, 0.5}};
  refused(s, "Poisson's ratio 0.5");
  s = steel_column(40);
  s.wall = WallKind::none;
  refused(s, "bottom wall");
  s.gravity = 0;
  s.gap = -1e-6;
  refused(s, "overlap");
}

TEST(GranularChain, RefusesATimeStepAboveTheStableStep) {
  ChainSpec s = steel_column(50);
  const Chain c = build_chain(s);
  const Impulse kick{Impulse::Kind::velocity, 1.0, 1, {}, {}};
  const double stable = Simulation::stable_step(c, kick);
  EXPECT_NO_THROW(Simulation(c, kick, stable));
  EXPECT_THROW(Simulation(c, kick, 1.01 * stable), InputError);
  // A horizontal chain at rest has no stiffness: no step can be derived.
  s.gravity = 0;
  s.wall = WallKind::none;
  EXPECT_THROW(Simulation(build_chain(s), Impulse{}), InputError);
}

TEST(GranularChain, StableStepBoundHoldsDuringTheRun) {
  // The bound puts the impulse's whole energy into one contact, so the run's stiffest contact
  // never needs a smaller step than the estimate: the health check passes at Δt = stable step
  // over the impact of 4 grains (the worst case here) on a column.
  const Chain c = build_chain(steel_column(60));
  Simulation sim(c, Impulse{Impulse::Kind::velocity, 2.0, 4, {}, {}}, std::nullopt, 1.0);
  for (int s = 0; s < 3000; ++s) {
    sim.step();
    if (s % 50 == 0) {
      ASSERT_NO_THROW(sim.health_check()) << s;
    }
  }
}

double max_energy_drift(double dt_fraction, long long steps_per_unit) {
  ChainSpec s = horizontal(60, 5e-3);
  const Chain c = build_chain(s);
  const Impulse kick{Impulse::Kind::velocity, 0.1, 1, {}, {}};
  Simulation sim(c, kick, dt_fraction * Simulation::stable_step(c, kick));
  const double e0 = sim.thermo().total;
  double drift = 0;
  // Until the wave is about 40 grains down (Nesterenko's V_s of the impact speed, an overestimate).
  const NesterenkoWave wave{c.kappa[0], c.mass[0], 2 * s.radius};
  const auto steps = static_cast<long long>(std::ceil(40 * wave.diameter / wave.speed(0.1) / sim.time_step()));
  for (long long k = 0; k < steps; ++k) {
    sim.step();
    if (k % steps_per_unit == 0) drift = std::max(drift, std::abs(sim.thermo().total - e0) / e0);
  }
  return drift;
}

TEST(GranularChain, VelocityVerletConservesEnergyTo1e8WithTheErrorFallingAsDtSquared) {
  // Δt = 2e-4 of the stable step (3.18e-9 s for these grains; the stable step bounds the
  // stiffest contact the impulse could make, the wave's own contacts are softer): velocity
  // Verlet's energy error is O((ωΔt)²), measured 3.1e-9 relative. Halving Δt must divide it by
  // 4 (measured 3.99; ±20% as the maximum is taken over sampled times).
  const double coarse = max_energy_drift(2e-4, 200);
  const double fine = max_energy_drift(1e-4, 400);
  EXPECT_LT(coarse, 1e-8);
  EXPECT_NEAR(coarse / fine, 4.0, 0.8);
}

TEST(GranularChain, ForceHistoryDeliversItsImpulseAndWork) {
  // A triangular push of 0.5 N over 20 µs on the top grain of a free horizontal chain: the
  // chain's momentum is the push's impulse J = ½·0.5 N·20 µs (velocity Verlet conserves momentum
  // exactly and the push enters as a trapezoid rule, which is exact for a piecewise-linear force
  // sampled at its nodes: 1e-12 relative), and the total energy equals the work done by the
  // push (the work's trapezoid rule is second order: 1e-6 relative at this step).
  ChainSpec s = horizontal(200, 5e-3);
  const Impulse push{Impulse::Kind::force, 0.0, 1, {0.0, 1e-5, 2e-5}, {0.0, 0.5, 0.0}};
  Simulation sim(build_chain(s), push, 1e-8);
  while (sim.time() < 1e-4) sim.step();
  double momentum = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) momentum += sim.chain().mass[i] * sim.velocity()[i];
  EXPECT_NEAR(momentum / 5e-6, 1.0, 1e-12);
  const Thermo t = sim.thermo();
  EXPECT_GT(t.external_work, 0.0);
  EXPECT_NEAR(t.total / t.external_work, 1.0, 1e-6);
}

TEST(GranularChain, ViscousDampingOnlyRemovesEnergyAndAWallReflectsTheWave) {
  // With γ > 0 the total energy never rises (beyond Verlet's O(Δt²) wiggle, 1e-9 relative here)
  // and ends well below the impulse's; without γ an elastic wall sends the wave back with the
  // energy intact (1e-6: Verlet at a coarser step than the conservation test).
  ChainSpec s = horizontal(40, 5e-3);
  s.wall = WallKind::elastic;
  s.wall_youngs_modulus = 70e9;
  s.wall_poisson_ratio = 0.33;
  const Impulse kick{Impulse::Kind::velocity, 0.1, 1, {}, {}};
  const auto run = [&](double damping) {
    s.damping = damping;
    const Chain c = build_chain(s);
    Simulation sim(c, kick, 0.002 * Simulation::stable_step(c, kick));
    const double e0 = sim.thermo().total;
    double previous = e0, rise = 0, wall_peak = 0;
    while (sim.time() < 2.5e-3) {  // the wave reaches the wall (40 grains at ~420 m/s) and returns
      sim.step();
      if (sim.step_count() % 100 == 0) {
        const double e = sim.thermo().total;
        rise = std::max(rise, (e - previous) / e0);
        previous = e;
      }
      wall_peak = std::max(wall_peak, sim.wall_force());
    }
    return std::array<double, 4>{previous / e0, rise, wall_peak, sim.velocity().front()};
  };
  const auto damped = run(0.5), elastic = run(0.0);
  EXPECT_LT(damped[1], 1e-9);
  EXPECT_LT(damped[0], 0.9);
  EXPECT_NEAR(elastic[0], 1.0, 1e-6);
  EXPECT_GT(elastic[2], 0.0);
}

TEST(GranularChain, HealthCheckStopsARunWhoseContactsOutgrewTheStep) {
  // A state compressed far beyond what the step was chosen for (contact 10 overlapping by
  // 1e-4 m, ~50 times the impulse's bound) makes the stiffest contact need a smaller step.
  ChainSpec s = horizontal(30, 5e-3);
  const Chain c = build_chain(s);
  const Impulse kick{Impulse::Kind::velocity, 0.1, 1, {}, {}};
  Simulation sim(c, kick, std::nullopt, 0.9);
  EXPECT_NO_THROW(sim.health_check());
  std::vector<double> w(c.size(), 0.0);
  for (std::size_t i = 0; i <= 10; ++i) w[i] = 1e-4;
  sim.restore(w, sim.velocity(), sim.force(), sim.contact_force(), 0, 0.0, 0.0);
  EXPECT_THROW(sim.health_check(), RunError);
  w[3] = std::nan("");
  sim.restore(w, sim.velocity(), sim.force(), sim.contact_force(), 0, 0.0, 0.0);
  EXPECT_THROW(sim.health_check(), RunError);
}

TEST(GranularChain, ThreadedLoopsGiveTheSameBitsAsOneThread) {
  // Above kThreadedGrains the force and kick loops are shared among threads; each element is
  // computed alone (no sums), so the result must not depend on the thread count at all.
  ChainSpec s = steel_column(static_cast<long long>(kThreadedGrains) + 1000);
  const Chain c = build_chain(s);
  const Impulse kick{Impulse::Kind::velocity, 1.0, 3, {}, {}};
  const auto run = [&](int threads) {
    omp_set_num_threads(threads);
    Simulation sim(c, kick);
    for (int k = 0; k < 20; ++k) sim.step();
    return sim.displacement();
  };
  const auto one = run(1), two = run(2);
  omp_set_num_threads(1);
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace shockfield::granular
