// Xu et al. (2015) aluminium (§4.1) in symmetric impact at ±1000 m/s: the steady shock state, energy and
// momentum conservation, and independence of the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/particles.hpp"
#include "strip.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

strip::Setup impact(int cells) {
  strip::Setup s;
  s.cells = cells;
  s.v_lower = 1000.0;
  s.v_upper = -1000.0;
  s.options.shape = mpm::ShapeKind::Gimp;  // points cross cells: GIMP (see test_waves ElasticWave)
  return s;
}

// T_H(V) by classical RK4 of seed eq. 7 from (V0, T0), written here independently of
// materials::Thermal.
double hugoniot_temperature(const materials::SolidMaterial& m, double rho) {
  const double c0 = m.eos.c0, l = m.eos.lambda, cv = m.thermal.heat_capacity, v0 = 1.0 / m.eos.rho0;
  const double gv = m.eos.rho0 * m.eos.gamma0;
  auto f = [&](double v, double t) {
    const double d = (l - 1.0) * v0 - l * v;
    return c0 * c0 * l * (v0 - v) * (v0 - v) / (cv * d * d * d) - gv * t;
  };
  const int n = 4000;
  const double h = (1.0 / rho - v0) / n;
  double t = m.thermal.initial_temperature;
  for (int i = 0; i < n; ++i) {
    const double v = v0 + i * h;
    const double k1 = f(v, t), k2 = f(v + h / 2, t + h / 2 * k1), k3 = f(v + h / 2, t + h / 2 * k2), k4 = f(v + h, t + h * k3);
    t += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return t;
}

}  // namespace

// Behind the steady shock, Up = 1000 m/s (symmetry): Us = c0 + λUp = 6690 m/s,
// P = ρ0·Us·Up = 18.06 GPa, ρ = ρ0·Us/(Us − Up) = 3174 kg/m³ (Rankine-Hugoniot with the paper's
// c0 = 5.35 km/s, λ = 1.34). Tolerance 2% (issue): the longitudinal stress also carries the
// ⅔σ_Y of the strength (≈ 0.1 GPa, 0.5%) and the MPM shock is smeared. The temperature is
// T_H(ρ) of eq. 7 plus the plastic heating W_p/c_v of eq. 8, both from the measured state.
TEST(AluminiumImpact, SteadyShockStateAt1000MetresPerSecond) {
  const auto al = materials::aluminium_seed000();
  const strip::Setup s = impact(200);
  auto sim = strip::make(s, al);
  const double len = s.cells * s.h;
  const double t1 = 0.3 * len / 6690.0, t2 = 0.6 * len / 6690.0;
  sim.run_until(t1);
  const double y1 = strip::front_from_top(strip::profile(sim.particles(), s.h), -500.0);
  sim.run_until(t2);
  const auto rows = strip::profile(sim.particles(), s.h);
  const double y2 = strip::front_from_top(rows, -500.0);
  const double us = (y2 - y1) / (t2 - t1) + 1000.0;  // lab front speed + the upstream material speed
  const double lo = 6 * s.h, hi = 0.6 * y2;
  auto avg = [&](auto field) { return strip::mean(rows, lo, hi, field); };
  const double p = -avg([](const strip::Row& r) { return r.syy; });
  const double rho = avg([](const strip::Row& r) { return r.rho; });
  const double up = avg([](const strip::Row& r) { return r.vy; });
  const double temp = avg([](const strip::Row& r) { return r.t; });
  const double wp = avg([](const strip::Row& r) { return r.wp; });
  EXPECT_NEAR(us, 6690.0, 0.02 * 6690.0);
  EXPECT_NEAR(p, 18.06e9, 0.02 * 18.06e9);
  EXPECT_NEAR(rho, 3174.0, 0.02 * 3174.0);
  EXPECT_NEAR(up, 0.0, 0.01 * 1000.0);
  // Temperature rise: 7% tolerance. Each point takes eq. 7 up to the smallest volume it reaches,
  // and the ringing behind the smeared MPM shock overshoots the final compression by ~1% in
  // density, which the steep T_H(V) turns into a few % more heating.
  const double t_ref = hugoniot_temperature(al, 2700.0 * 6690.0 / 5690.0) + wp / al.thermal.heat_capacity;
  EXPECT_NEAR(temp - 300.0, t_ref - 300.0, 0.07 * (t_ref - 300.0));
  RecordProperty("Us", std::to_string(us));
  RecordProperty("P", std::to_string(p));
  RecordProperty("rho", std::to_string(rho));
  RecordProperty("T", std::to_string(temp));
  RecordProperty("T_ref", std::to_string(t_ref));
}

// Where the 7 % temperature excess above comes from (docs/theory/mpm.md, "Shock temperature"):
// each point follows eq. 7 down to the smallest volume it reaches and the isentrope
// T ∝ exp(−ρ0γ0·ΔV) back up from there, and the ringing behind the MPM shock overshoots the final
// density (3191.6 against 3173.3 kg/m³ at C_L = 0.3). (a) With the default viscosity the mean
// temperature equals that path, T_H(V_min)·exp(−ρ0γ0(V − V_min)) + W_p/c_v averaged over the
// points, within 1 % of the rise (measured 0.7 K of 204 K; the rest is the RK2 path integration).
// (b) With C_L = 0.5 the overshoot is gone (ρ_max within 0.1 % of ρ) and T meets the plain eq.-7
// reference T_H(ρ) + W_p/c_v within 1.5 % of the rise (measured 1.3 K); not the default, as it
// would change every MPM result recorded so far (see the theory note).
TEST(AluminiumImpact, TemperatureExcessIsTheShockOvershoot) {
  auto measure = [](double linear_viscosity) {
    auto al = materials::aluminium_seed000();
    al.viscosity.linear = linear_viscosity;
    const strip::Setup s = impact(200);
    auto sim = strip::make(s, al);
    const double len = s.cells * s.h;
    sim.run_until(0.6 * len / 6690.0);
    const double gv = al.eos.rho0 * al.eos.gamma0, cv = al.thermal.heat_capacity;
    double n = 0, t = 0, path = 0, plain = 0, rho = 0, rho_max = 0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i) {
      const double y = std::abs(sim.particles().x[i][1]);
      if (y < 6 * s.h || y > 0.3 * len) continue;  // behind the front, away from the impact plane
      const auto& st = sim.particles().state[i];
      const double r = sim.particles().density(i), v_min = st.shock_volume, heat = st.plastic_work / cv;
      n += 1, t += st.temperature, rho += r, rho_max += 1.0 / v_min;
      path += hugoniot_temperature(al, 1.0 / v_min) * std::exp(-gv * (1.0 / r - v_min)) + heat;
      plain += hugoniot_temperature(al, r) + heat;
    }
    return std::array<double, 5>{t / n, path / n, plain / n, rho / n, rho_max / n};
  };
  const auto [t, path, plain, rho, rho_max] = measure(0.3);
  EXPECT_GT(rho_max, rho * 1.003);  // the overshoot is there ...
  EXPECT_GT(t - plain, 0.03 * (plain - 300.0));  // ... and so is the excess
  EXPECT_NEAR(t - 300.0, path - 300.0, 0.01 * (path - 300.0));
  const auto [t5, path5, plain5, rho5, rho_max5] = measure(0.5);
  EXPECT_LT(rho_max5, rho5 * 1.001);
  EXPECT_NEAR(t5 - 300.0, plain5 - 300.0, 0.015 * (plain5 - 300.0));
  RecordProperty("T_default", std::to_string(t));
  RecordProperty("T_path", std::to_string(path));
  RecordProperty("T_plain", std::to_string(plain));
  RecordProperty("T_CL05", std::to_string(t5));
  RecordProperty("T_plain_CL05", std::to_string(plain5));
}

// Mass: particle masses are fixed, and the grid carries exactly the particle mass (partition of
// unity, round-off). Momentum: internal forces sum to zero (Σ_i ∇N_i = 0), so the total stays at
// its initial zero to round-off (1e-9 of M·v). Energy: kinetic + internal within 1% of the initial
// kinetic energy (FLIP-MUSL is not exactly conservative; the measured drift is reported: −0.33 %,
// and −0.60 % with XPIC(2) and the smoothed dilatation (−0.72 % before the smoothing had its B-bar
// force): XPIC takes the energy of the modes it filters).
TEST(AluminiumImpact, ConservesMassMomentumEnergy) {
  const auto al = materials::aluminium_seed000();
  for (const bool filtered : {false, true}) {  // also with XPIC(2) and the smoothed dilatation
    strip::Setup s = impact(100);
    s.options.xpic_order = filtered ? 2 : 0;
    s.options.smooth_dilatation = filtered;
    auto sim = strip::make(s, al);
    const mpm::Totals t0 = mpm::totals(sim.particles());
    double worst_grid_mass = 0.0;
    sim.add_hook(mpm::Stage::AfterGridUpdate, [&](mpm::Simulation& run) {
      double m = 0.0;
      for (double mi : run.grid().mass) m += mi;
      worst_grid_mass = std::max(worst_grid_mass, std::abs(m - t0.mass) / t0.mass);
    });
    sim.run_until(0.8 * s.cells * s.h / 6690.0);
    const mpm::Totals t1 = mpm::totals(sim.particles());
    EXPECT_EQ(t1.mass, t0.mass);
    EXPECT_LT(worst_grid_mass, 1e-12);
    EXPECT_LT(t1.momentum.norm(), 1e-9 * t0.mass * 1000.0);
    EXPECT_GT(t1.internal, 0.3 * t0.kinetic);  // a real transfer happened
    const double drift = (t1.total() - t0.total()) / t0.total();
    EXPECT_LT(std::abs(drift), 0.01);
    RecordProperty(filtered ? "energy_drift_filtered" : "energy_drift", std::to_string(drift));
  }
}

// Every particle-to-grid sum is formed in a fixed order (transfer.hpp), so 1 and 2 threads give bit-identical
// results (stronger than "beyond round-off"); also with XPIC(2) and the smoothed dilatation.
TEST(AluminiumImpact, IndependentOfThreadCount) {
  const auto al = materials::aluminium_seed000();
  auto run = [&](int threads, const mpm::SimulationOptions& options) {
    omp_set_num_threads(threads);
    strip::Setup s = impact(20);
    s.options = options;
    auto sim = strip::make(s, al);
    for (int i = 0; i < 40; ++i) sim.step();
    omp_set_num_threads(omp_get_num_procs());
    return sim.particles();
  };
  mpm::SimulationOptions linear, gimp, filtered;
  gimp.shape = filtered.shape = mpm::ShapeKind::Gimp;
  filtered.xpic_order = 2;
  filtered.smooth_dilatation = true;
  for (const auto& options : {linear, gimp, filtered}) {
    const mpm::Particles a = run(1, options), b = run(2, options);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t p = 0; p < a.size(); ++p) {
      ASSERT_EQ(a.x[p], b.x[p]) << p;
      ASSERT_EQ(a.v[p], b.v[p]) << p;
      ASSERT_EQ(a.state[p].pressure, b.state[p].pressure) << p;
      ASSERT_EQ(a.state[p].temperature, b.state[p].temperature) << p;
    }
  }
}
