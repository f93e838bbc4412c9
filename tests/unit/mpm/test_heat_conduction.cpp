// MPM heat conduction (heat_conduction.hpp): decay of a sinusoidal temperature against the
// analytic exp(−α k² t), conservation of Σ m c_v T and of the total energy in a closed box, the
// diffusion limit of the stable step, thread-count independence, and the switch being a no-op
// when every conductivity is 0.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/heat_conduction.hpp"
#include "shockfield/mpm/simulation.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

constexpr double kCell =
    1e-7;  // h [m]: the conduction time λ²/(4π²α) is then ~500 mechanical steps

// Aluminium with γ0 = 0: the pressure does not depend on e, so a block at rest stays at rest
// while conduction changes its internal energy (pure heat conduction).
materials::SolidMaterial still_aluminium() {
  auto al = materials::aluminium_seed000();
  al.eos.gamma0 = 0.0;
  return al;
}

// A block filling the grid, 2 × 2 points per cell, T = T0 + A sin(2π x / L).
mpm::Particles sine_block(const mpm::GridSpec& g, const materials::SolidMaterial& mat,
                          double amplitude) {
  mpm::Particles p;
  const double s = 0.5 * kCell;
  const double lx = g.length(0);
  for (int j = 0; j < 2 * g.cells[1]; ++j)
    for (int i = 0; i < 2 * g.cells[0]; ++i) {
      const Vec3 x(g.origin[0] + (i + 0.5) * s, g.origin[1] + (j + 0.5) * s, 0.0);
      p.add(x, Vec3::Zero(), s * s, Vec3::Constant(0.5 * s), mat, 0);
      p.state.back().temperature +=
          amplitude * std::sin(2.0 * std::numbers::pi * (x[0] - g.origin[0]) / lx);
    }
  return p;
}

mpm::GridSpec grid(std::array<int, 3> cells, bool periodic) {
  mpm::GridSpec g;
  g.dim = 2;
  g.cell_size = Vec3::Constant(kCell);
  g.cells = cells;
  g.periodic = {periodic, periodic, false};
  if (!periodic)
    for (auto& w : g.walls) w = {mpm::Wall::Slip, mpm::Wall::Slip};
  return g;
}

mpm::SimulationOptions conducting(mpm::ShapeKind shape = mpm::ShapeKind::Linear) {
  mpm::SimulationOptions o;
  o.shape = shape;
  o.heat_conduction = true;
  return o;
}

// 2/N Σ_p (T_p − T0) sin(k x_p): the amplitude of the sine mode.
double amplitude(const mpm::Simulation& sim, double t0) {
  const auto& p = sim.particles();
  const double k = 2.0 * std::numbers::pi / sim.grid().spec().length(0);
  double a = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q)
    a += (p.state[q].temperature - t0) * std::sin(k * p.x[q][0]);
  return 2.0 * a / static_cast<double>(p.size());
}

double heat(const mpm::Simulation& sim) {  // Σ m c_v T
  double h = 0.0;
  const auto& p = sim.particles();
  for (std::size_t q = 0; q < p.size(); ++q)
    h += p.mass[q] *
         sim.materials()[static_cast<std::size_t>(p.material[q])].thermal.heat_capacity *
         p.state[q].temperature;
  return h;
}

}  // namespace

TEST(HeatConduction, SineModeDecaysAsExpMinusAlphaK2T) {
  const auto al = still_aluminium();
  const mpm::GridSpec g = grid({32, 2, 0}, true);
  const double t0 = al.thermal.initial_temperature, a0 = 50.0;
  mpm::Simulation sim(g, {al}, sine_block(g, al, a0), conducting());
  const double alpha = al.thermal.conductivity / (al.eos.rho0 * al.thermal.heat_capacity);
  const double k = 2.0 * std::numbers::pi / g.length(0);
  const double t_end = 1.0 / (alpha * k * k);  // one e-folding
  const double a_start = amplitude(sim, t0);
  EXPECT_NEAR(a_start, a0, 1e-9 * a0);
  sim.run_until(t_end);
  EXPECT_GT(sim.step_count(), 100);
  const double ratio = amplitude(sim, t0) / a_start;
  EXPECT_NEAR(ratio, std::exp(-1.0), 0.02 * std::exp(-1.0)) << "steps " << sim.step_count();
  EXPECT_EQ(totals(sim.particles()).kinetic, 0.0);  // γ0 = 0: conduction alone, nothing moves
}

TEST(HeatConduction, OffOrZeroConductivityLeavesTemperatureAlone) {
  auto al = still_aluminium();
  const mpm::GridSpec g = grid({16, 2, 0}, true);
  mpm::SimulationOptions off;
  off.shape = mpm::ShapeKind::Linear;
  mpm::Simulation sim_off(g, {al}, sine_block(g, al, 50.0), off);
  al.thermal.conductivity = 0.0;
  mpm::Simulation sim_zero(g, {al}, sine_block(g, al, 50.0), conducting());  // accepted, a no-op
  for (int s = 0; s < 20; ++s) sim_off.step(), sim_zero.step();
  const auto start = sine_block(g, al, 50.0);
  for (std::size_t q = 0; q < start.size(); ++q) {
    ASSERT_EQ(sim_off.particles().state[q].temperature, start.state[q].temperature);
    ASSERT_EQ(sim_zero.particles().state[q].temperature, start.state[q].temperature);
  }
  EXPECT_EQ(sim_off.last_time_step(), sim_zero.last_time_step());
}

TEST(HeatConduction, ClosedBoxConservesHeatAndTotalEnergy) {
  // Slip walls all round (insulated), a hot square in a cold block, two materials with
  // different c_v and k.
  auto cold = still_aluminium();
  auto hot = still_aluminium();
  hot.thermal.heat_capacity = 2.0 * cold.thermal.heat_capacity;
  hot.thermal.conductivity = 0.3 * cold.thermal.conductivity;
  hot.thermal.initial_temperature = 900.0;
  const mpm::GridSpec g = grid({12, 10, 0}, false);
  mpm::Particles p;
  const double s = 0.5 * kCell;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 24; ++i) {
      const bool inside = i >= 6 && i < 14 && j >= 4 && j < 12;
      p.add(Vec3((i + 0.5) * s, (j + 0.5) * s, 0), Vec3::Zero(), s * s, Vec3::Constant(0.5 * s),
            inside ? hot : cold, inside ? 1 : 0);
    }
  mpm::Simulation sim(g, {cold, hot}, std::move(p), conducting());
  const double heat0 = heat(sim), energy0 = totals(sim.particles()).total();
  double spread0 = 0.0;
  for (const auto& st : sim.particles().state) spread0 = std::max(spread0, st.temperature - 300.0);
  for (int s2 = 0; s2 < 300; ++s2) sim.step();
  const double heat1 = heat(sim), energy1 = totals(sim.particles()).total();
  double hottest = 0.0;
  for (const auto& st : sim.particles().state) hottest = std::max(hottest, st.temperature - 300.0);
  EXPECT_LT(hottest, 0.9 * spread0);  // heat has flowed
  EXPECT_NEAR(heat1, heat0, 1e-13 * heat0);
  // Σ m e moves by Σ m c_v ΔT, which conduction keeps at zero (Σ_i Q_i = 0); nothing moves.
  EXPECT_EQ(totals(sim.particles()).kinetic, 0.0);
  EXPECT_NEAR(energy1 - energy0, 0.0, 1e-13 * heat0);
  // ... and each point's e moved by exactly c_v ΔT (e and T start at 0 and T0).
  const auto& p1 = sim.particles();
  for (std::size_t q = 0; q < p1.size(); ++q) {
    const auto& th = sim.materials()[static_cast<std::size_t>(p1.material[q])].thermal;
    EXPECT_NEAR(p1.state[q].energy, th.heat_capacity * (p1.state[q].temperature - th.initial_temperature),
                1e-9 * th.heat_capacity * 600.0)
        << q;
  }
}

TEST(HeatConduction, StableStepHasTheDiffusionLimit) {
  auto al = still_aluminium();
  al.thermal.conductivity *= 100.0;  // the diffusion limit now binds
  const mpm::GridSpec g = grid({8, 2, 0}, true);
  mpm::Simulation sim(g, {al}, sine_block(g, al, 10.0), conducting());
  const double alpha = al.thermal.conductivity / (al.eos.rho0 * al.thermal.heat_capacity);
  const double limit = 0.3 * kCell * kCell / (2.0 * 2.0 * alpha);
  EXPECT_DOUBLE_EQ(sim.stable_time_step(), limit);
  sim.step();
  EXPECT_DOUBLE_EQ(sim.last_time_step(), limit);
  sim.step();  // second step through the cached fastest signal
  EXPECT_DOUBLE_EQ(sim.last_time_step(), limit);
}

TEST(HeatConduction, IndependentOfThreadCountBitwise) {
  // Random points (GIMP, periodic, moving, real γ0) so the slab passes and wrap-round slabs all
  // work.
  const auto al = materials::aluminium_seed000();
  mpm::GridSpec g = grid({6, 7, 0}, true);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  mpm::Particles p;
  for (int q = 0; q < 300; ++q) {
    const Vec3 x(u(rng) * g.length(0), u(rng) * g.length(1), 0.0);
    p.add(x, Vec3(50.0 * (u(rng) - 0.5), 50.0 * (u(rng) - 0.5), 0),
          0.25 * kCell * kCell * (0.5 + u(rng)), Vec3::Constant(0.2 * kCell), al, 0);
    p.state.back().temperature += 400.0 * u(rng);
  }
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    mpm::Simulation sim(g, {al}, p, conducting(mpm::ShapeKind::Gimp));
    for (int s = 0; s < 15; ++s) sim.step();
    omp_set_num_threads(1);
    return sim.particles();
  };
  const auto one = run(1), two = run(2);
  for (std::size_t q = 0; q < one.size(); ++q) {
    ASSERT_EQ(one.state[q].temperature, two.state[q].temperature) << q;
    ASSERT_EQ(one.state[q].energy, two.state[q].energy) << q;
    ASSERT_EQ(one.x[q], two.x[q]) << q;
  }
  double changed = 0.0;
  for (std::size_t q = 0; q < one.size(); ++q)
    changed = std::max(changed, std::abs(one.state[q].temperature - p.state[q].temperature));
  EXPECT_GT(changed, 1.0);
}

TEST(HeatConduction, NegativeConductivityIsRefused) {
  auto al = materials::aluminium_seed000();
  al.thermal.conductivity = -1.0;
  EXPECT_THROW(al.validate(), InputError);
}
