// BGK DBM: conservation on a periodic lattice, reflecting walls, thread-count independence and
// the refusal of unstable settings and broken states.
#include "shockfield/dbm/simulation.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

Lattice square(int n) {
  Lattice l;
  l.nx = l.ny = n;
  l.dx = l.dy = 1.0 / n;
  return l;
}

BgkSettings settings_for(const Lattice& l, double max_speed) {
  BgkSettings s;
  s.dt = 0.4 * l.dx / max_speed;
  s.tau = 2.0 * s.dt;
  return s;
}

// A smooth 2D blob: density and temperature bumps with a swirl.
Macro blob(double x, double y) {
  const double r2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
  const double g = std::exp(-r2 / 0.02);
  return {1.0 + 0.3 * g, 0.2 * g * (y - 0.5), -0.2 * g * (x - 0.5), 1.0 + 0.2 * g};
}

}  // namespace

TEST(DbmSimulation, ConservesMassMomentumEnergy) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const Lattice l = square(32);
  for (auto kind : {BoundaryKind::periodic, BoundaryKind::reflecting}) {
    Boundaries bc;
    for (auto& side : bc.side) side.kind = kind;
    Simulation sim(model, l, bc, settings_for(l, model.max_speed()));
    sim.initialize(blob);
    const auto before = sim.totals();
    for (int n = 0; n < 100; ++n) sim.step();
    sim.check_state();
    const auto after = sim.totals();
    EXPECT_NEAR(after[0], before[0], 1e-12 * before[0]);
    EXPECT_NEAR(after[3], before[3], 1e-12 * before[3]);
    if (kind == BoundaryKind::periodic) {  // walls exchange momentum with the fluid
      EXPECT_NEAR(after[1], before[1], 1e-13);
      EXPECT_NEAR(after[2], before[2], 1e-13);
    }
  }
}

TEST(DbmSimulation, ResultsIndependentOfThreadCount) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const Lattice l = square(24);
  std::vector<double> result[2];
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Simulation sim(model, l, Boundaries{}, settings_for(l, model.max_speed()));
    sim.initialize(blob);
    for (int n = 0; n < 8; ++n) sim.step();
    result[threads - 1] = sim.f();
  }
  omp_set_num_threads(1);
  EXPECT_EQ(result[0], result[1]);
}

TEST(DbmSimulation, FusedStagesEqualTheStoredRightHandSide) {
  // Without a source each Runge–Kutta stage is completed row by row, chunk by chunk; with one
  // L(f) is stored first. A source adding nothing must give the same bits, also across the
  // 64-cell chunks of a row.
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l = square(8);
  l.nx = 150;
  std::vector<double> result[2];
  for (int with_source : {0, 1}) {
    Simulation sim(model, l, Boundaries{}, settings_for(l, model.max_speed()));
    if (with_source) sim.set_source([](const std::vector<double>&, std::vector<double>&) {});
    sim.initialize(blob);
    for (int n = 0; n < 4; ++n) sim.step();
    for (int k = 0; k < model.size(); ++k)  // interior cells (ghosts are refilled before use)
      for (int j = 0; j < l.ny; ++j)
        for (int i = 0; i < l.nx; ++i)
          result[with_source].push_back(sim.f()[k * l.cells() + l.at(i, j)]);
  }
  EXPECT_EQ(result[0], result[1]);
}

TEST(DbmSimulation, RefusesUnstableSettings) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const Lattice l = square(16);
  auto message = [&](BgkSettings s) -> std::string {
    try {
      Simulation sim(model, l, Boundaries{}, s);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  BgkSettings s = settings_for(l, model.max_speed());
  BgkSettings bad = s;
  bad.tau = s.dt / 3.0;
  EXPECT_NE(message(bad).find("dt/tau = 3 > 2.5"), std::string::npos) << message(bad);
  bad = s;
  bad.dt = 3.0 * l.dx / model.max_speed();
  bad.tau = bad.dt;
  EXPECT_NE(message(bad).find("Courant number"), std::string::npos) << message(bad);
  bad = s;
  bad.tau = -1.0;
  EXPECT_NE(message(bad).find("tau = -1 must be a positive number"), std::string::npos);
  bad = s;
  bad.gamma = 2.5;
  EXPECT_NE(message(bad).find("gamma = 2.5 is outside"), std::string::npos);
  Boundaries half;
  half.side[0].kind = BoundaryKind::outflow;
  EXPECT_THROW(Simulation(model, l, half, s), InputError);
  EXPECT_THROW(boundary_kind("sticky"), InputError);
}

TEST(DbmSimulation, BrokenStateIsDiagnosed) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const Lattice l = square(8);
  Simulation sim(model, l, Boundaries{}, settings_for(l, model.max_speed()));
  sim.initialize(blob);
  sim.f()[l.at(3, 5)] = std::nan("");
  try {
    sim.check_state();
    FAIL() << "NaN not detected";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("cell (3, 5)"), std::string::npos) << e.what();
  }
}

TEST(DbmSimulation, InflowOutflowCarriesAUniformStreamUnchanged) {
  // A uniform supersonic-free stream entering at x = 0 and leaving at x = 1 is a steady state;
  // a denser inflow state enters from the left.
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = 40;
  l.ny = 2;
  l.dx = l.dy = 1.0 / 40;
  const Macro stream{1.0, 0.5, 0.0, 1.0};
  Boundaries bc;
  bc.side[0] = {BoundaryKind::inflow, stream};
  bc.side[1].kind = BoundaryKind::outflow;
  Simulation sim(model, l, bc, settings_for(l, model.max_speed()));
  sim.initialize([&](double, double) { return stream; });
  for (int n = 0; n < 50; ++n) sim.step();
  for (int i = 0; i < l.nx; ++i) {
    EXPECT_NEAR(sim.macro(i, 1).rho, 1.0, 1e-12);
    EXPECT_NEAR(sim.macro(i, 1).ux, 0.5, 1e-12);
  }
  Boundaries denser = bc;
  denser.side[0].state.rho = 1.2;
  Simulation fed(model, l, denser, settings_for(l, model.max_speed()));
  fed.initialize([&](double, double) { return stream; });
  const double mass = fed.totals()[0];
  while (fed.time() < 0.6) fed.step();
  fed.check_state();
  EXPECT_GT(fed.macro(2, 0).rho, 1.1);
  EXPECT_GT(fed.totals()[0], 1.03 * mass);
}
