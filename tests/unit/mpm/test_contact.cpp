// Multi-body contact (contact.hpp; docs/theory/mpm.md, "Contact between bodies"): elastic bars in
// uniaxial strain (strip.hpp: plane strain, periodic along x, so the bar wave speed is the
// longitudinal c = √((K + 4G/3)/ρ)) that collide and separate as the 1D theory says, against the
// glued bars of a shared grid field.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "plastic_bar.hpp"
#include "strip.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

void record(const std::string& key, double value) { ::testing::Test::RecordProperty(key, std::to_string(value)); }

// Elastic (yield far above the stress of the impact) aluminium of plastic_bar.hpp:
// c = √((K + 4G/3)/ρ) = 6549.7 m/s. No linear artificial viscosity (C_L = 0; the quadratic term
// stays): the impact sends linear, non-steepening waves, which C_L smears over many cells, and a
// smeared release front reaching the interface lets the bars part before all of it has arrived
// (exit speed 2.5 / 1.7 / 1.2 % low at 100 / 200 / 400 cells with the wave tests' C_L = 0.06,
// 1.9 / 1.2 / 0.7 % with C_L = 0).
constexpr double kH = 1e-3;
materials::SolidMaterial elastic() {
  auto m = materials::elastic_plastic("elastic_al", 2703.0, 77.11e9, 0.334, 1e12);
  m.viscosity.linear = 0.0;
  return m;
}
double wave_speed() { return plastic_bar::Material{"", 2703.0, 77.11e9, 0.334, 1e12}.cl(); }

struct Body {
  double mass = 0.0, momentum = 0.0, lateral = 0.0;  ///< per metre of thickness; momentum along y and x
  double lowest = std::numeric_limits<double>::infinity(), highest = -std::numeric_limits<double>::infinity();
  double velocity() const { return momentum / mass; }
  double lateral_velocity() const { return lateral / mass; }
};
struct State {
  Body lower, upper;
  double gap() const { return upper.lowest - lower.highest; }  ///< between the facing rows of points
};
State measure(const mpm::Particles& p) {
  State s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Body& b = p.body[i] == 0 ? s.lower : s.upper;
    b.mass += p.mass[i];
    b.momentum += p.mass[i] * p.v[i][1];
    b.lateral += p.mass[i] * p.v[i][0];
    b.lowest = std::min(b.lowest, p.x[i][1]);
    b.highest = std::max(b.highest, p.x[i][1]);
  }
  return s;
}

struct Collision {
  double last_contact = 0.0;  ///< end of the last step with a contact node [s]
  double gap_time = 0.0;      ///< when the gap, extrapolated back from after separation, was the initial one [s]
  double half_force = 0.0;    ///< last time the contact force was at least half the 1D value [s]
  State end;                  ///< at the end of the run
  double energy0 = 0.0, energy1 = 0.0, momentum_error = 0.0, momentum_scale = 0.0;
};

// Lower bar of `cells` cells at v_lower, upper bar of `cells_upper` at v_upper (strip.hpp: 2 cells
// wide), run to `t_end`. `half_force` is the
// 1D contact force of equal impedances, ρc·(v_lower − v_upper)/2 times the strip width.
Collision collide(int cells, int cells_upper, double v_lower, double v_upper, bool contact, double t_end,
                  double friction = 0.0, double lateral = 0.0) {
  const double half_force = 2703.0 * wave_speed() * 0.5 * (v_lower - v_upper) * 2 * kH;
  strip::Setup s;
  s.h = kH;
  s.cells = cells;
  s.cells_upper = cells_upper;
  s.v_lower = v_lower;
  s.v_upper = v_upper;
  s.options.shape = mpm::ShapeKind::Gimp;
  s.options.contact.enabled = contact;
  s.options.contact.friction = friction;
  auto sim = strip::make(s, elastic());
  for (std::size_t i = 0; i < sim.particles().size(); ++i)  // ±lateral along x: the bars slide past each other
    sim.particles().v[i][0] = sim.particles().body[i] == 0 ? lateral : -lateral;
  Collision c;
  const mpm::Totals t0 = mpm::totals(sim.particles());
  c.energy0 = t0.total();
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    c.momentum_scale += sim.particles().mass[i] * std::abs(sim.particles().v[i][1]);
  const double gap0 = measure(sim.particles()).gap();
  std::vector<std::pair<double, double>> gaps;  // (t, gap)
  while (sim.time() < t_end * (1 - 1e-12)) {
    sim.step(t_end - sim.time());
    if (sim.contact_stats().nodes > 0) c.last_contact = sim.time();
    if (sim.contact_stats().force >= 0.5 * half_force) c.half_force = sim.time();
    gaps.emplace_back(sim.time(), measure(sim.particles()).gap());
  }
  // Least-squares line through the gaps after the bars parted (the last 80 % of the time since).
  double sum_t = 0, sum_g = 0, sum_tt = 0, sum_tg = 0;
  int n = 0;
  for (const auto& [t, g] : gaps)
    if (t >= c.last_contact + 0.2 * (t_end - c.last_contact))
      sum_t += t, sum_g += g, sum_tt += t * t, sum_tg += t * g, ++n;
  const double slope = (n * sum_tg - sum_t * sum_g) / (n * sum_tt - sum_t * sum_t);
  const double intercept = (sum_g - slope * sum_t) / n;
  c.gap_time = (gap0 - intercept) / slope;
  c.end = measure(sim.particles());
  const mpm::Totals t1 = mpm::totals(sim.particles());
  c.energy1 = t1.total();
  c.momentum_error = std::abs(t1.momentum[1] - t0.momentum[1]);
  return c;
}

}  // namespace

// Two equal bars (400 cells, 0.4 m each) at ±10 m/s. 1D theory (equal impedances): the interface
// is at rest under σ = ρcv until the releases from the free ends return at 2L/c = 122.1 µs; then
// the bars part at ∓v, stress-free. Measured: contact ends at 1.0035 × 2L/c by the last contact
// node, 0.9975 by the contact force's half-crossing, 1.0032 by the gap extrapolated back; exit speed
// 9.928 m/s (−0.7 %, the smeared release, see elastic()); momentum 7e-14 of Σm|v|; total energy
// +0.12 %. Bounds: 1 % (the issue's), round-off (1e-12) and 0.5 % (the drift of the Al impact
// test, 0.33 %, and of glued bars at 100 cells and C_L = 0.06, −0.6 %, are of that order; the
// contact's inelastic normal correction is part of what this bounds).
TEST(Contact, EqualBarsSeparateWithSwappedVelocities) {
  const double v = 10.0, len = 400 * kH, t_contact = 2 * len / wave_speed();
  EXPECT_NEAR(wave_speed(), 6549.7, 0.1);
  const auto r = collide(400, 400, v, -v, true, 2.5 * len / wave_speed());
  EXPECT_NEAR(r.last_contact, t_contact, 0.01 * t_contact);
  EXPECT_NEAR(r.half_force, t_contact, 0.01 * t_contact);
  EXPECT_NEAR(r.gap_time, t_contact, 0.01 * t_contact);
  EXPECT_NEAR(r.end.lower.velocity(), -v, 0.01 * v);
  EXPECT_NEAR(r.end.upper.velocity(), v, 0.01 * v);
  EXPECT_LT(r.momentum_error, 1e-12 * r.momentum_scale);
  EXPECT_NEAR(r.energy1, r.energy0, 0.005 * r.energy0);
  EXPECT_GT(r.end.gap(), 0.5 * kH + 0.9 * v * len / wave_speed());  // apart for L/(2c) at 2v
  record("contact_time_last_node", r.last_contact / t_contact);
  record("contact_time_half_force", r.half_force / t_contact);
  record("contact_time_gap", r.gap_time / t_contact);
  record("exit_speed", r.end.upper.velocity() / v);
  record("energy_drift", r.energy1 / r.energy0 - 1);
}

// A striker of L1 = 200 cells at 10 m/s onto a target of L2 = 600 cells at rest. 1D theory (equal
// impedances): contact for 2L1/c = 61.1 µs under ρc·v/2; the striker leaves at rest and the
// target carries its momentum, mean velocity v·L1/L2. (The two stay touching without force until
// the target's end jumps away at 2L2/c, after this run.) Measured: contact force at half its value
// until 1.0063 × 2L1/c, striker −0.185 m/s (1.85 % of v: the smeared release of a 200-cell striker,
// as the equal bars' exit speed is 1.2 % low at 200 cells; 1 % would take a 400-cell striker and a
// 1200-cell target, too slow here), target 1.0185 of v·L1/L2 (momentum conservation). Bounds 1 %
// on the contact time, 2 % of v on the exit velocities.
TEST(Contact, UnequalBarsAgainstOneDimensionalTheory) {
  const double v = 10.0, c = wave_speed(), t_contact = 2 * 200 * kH / c;
  const auto r = collide(200, 600, v, 0.0, true, 1.5 * t_contact);
  EXPECT_NEAR(r.half_force, t_contact, 0.01 * t_contact);
  EXPECT_NEAR(r.end.lower.velocity(), 0.0, 0.02 * v);
  EXPECT_NEAR(r.end.upper.velocity(), v / 3, 0.02 * v / 3);
  // 1.4e-10 of Σm|v|, with or without contact: the existing mass floor (nodes lighter than 1e-9 of a
  // point carry no velocity), met here at the ends of the target moving through the grid.
  EXPECT_LT(r.momentum_error, 1e-9 * r.momentum_scale);
  record("contact_time_half_force", r.half_force / t_contact);
  record("striker_exit_over_v", r.end.lower.velocity() / v);
  record("target_over_theory", r.end.upper.velocity() / (v / 3));
}

// Without contact the bodies share one grid field (the behaviour before contact): at 3L/c the two
// bars at ±10 m/s are still joined (gap within 0.1 h of the initial h/2, each bar's mean velocity
// under 1 % of v), where with contact they have parted at ∓v.
TEST(Contact, OffKeepsBarsGlued) {
  const double v = 10.0, len = 100 * kH, c = wave_speed();
  const auto glued = collide(100, 100, v, -v, false, 3.0 * len / c);
  EXPECT_NEAR(glued.end.gap(), 0.5 * kH, 0.1 * kH);
  EXPECT_LT(std::abs(glued.end.lower.velocity()), 0.01 * v);
  EXPECT_EQ(glued.last_contact, 0.0);  // no contact pass without contact
  const auto parted = collide(100, 100, v, -v, true, 3.0 * len / c);
  EXPECT_GT(parted.end.gap(), 0.5 * kH + 0.9 * 2 * v * len / c);  // apart for L/c at 2v
  EXPECT_LT(parted.end.lower.velocity(), -0.97 * v);
}

// Coulomb friction: the equal bars at ±10 m/s also sliding past each other at ±10 m/s along x.
// Frictionless, the lateral velocities are unchanged. With μ = 0.1 the interface slides throughout
// and each bar loses μ × its normal impulse per unit mass (v + exit speed) of lateral velocity:
// measured 8.0188 m/s against 8.0188 from the measured normal impulse. With μ = 100 it sticks: the
// interface is at rest laterally, a shear wave of τ = ρ c_s u runs into each bar for the contact
// time 2L/c, and the lateral velocity left is u(1 − 2c_s/c) = 0.015 m/s (c_s = √(G/ρ) = 3268 m/s;
// the wave reflected at the far end comes back after 2L/c_s, too late); measured −0.069 m/s.
TEST(Contact, FrictionSlidesAndSticks) {
  const double v = 10.0, u = 10.0, len = 100 * kH, c = wave_speed(), t_end = 2.5 * len / c;
  const auto free = collide(100, 100, v, -v, true, t_end, 0.0, u);
  EXPECT_NEAR(free.end.lower.lateral_velocity(), u, 1e-6 * u);
  const auto slide = collide(100, 100, v, -v, true, t_end, 0.1, u);
  const double normal = slide.end.upper.velocity() + v;  // normal impulse per unit mass of each bar
  EXPECT_NEAR(slide.end.lower.lateral_velocity(), u - 0.1 * normal, 0.01 * u);
  EXPECT_NEAR(slide.end.upper.lateral_velocity(), -(u - 0.1 * normal), 0.01 * u);
  const auto stick = collide(100, 100, v, -v, true, t_end, 100.0, u);
  const plastic_bar::Material al{"", 2703.0, 77.11e9, 0.334, 1e12};
  const double left = u * (1 - 2 * std::sqrt(al.g() / al.rho) / c);
  EXPECT_NEAR(stick.end.lower.lateral_velocity(), left, 0.02 * u);
  EXPECT_NEAR(stick.end.upper.lateral_velocity(), -left, 0.02 * u);
  record("lateral_mu0", free.end.lower.lateral_velocity());
  record("lateral_mu0.1", slide.end.lower.lateral_velocity());
  record("lateral_mu100", stick.end.lower.lateral_velocity());
}

// The contact law corrects each node on its own (no sums across nodes): the bars' impact and
// separation are bit-identical with 1 and 2 threads.
TEST(Contact, IndependentOfThreadCount) {
  strip::Setup s;
  s.h = kH;
  s.cells = 50;
  s.v_lower = 10.0;
  s.v_upper = -10.0;
  s.options.shape = mpm::ShapeKind::Gimp;
  s.options.contact.enabled = true;
  s.options.contact.friction = 0.2;
  const int threads = omp_get_max_threads();
  std::vector<mpm::Particles> out;
  for (int n : {1, 2}) {
    omp_set_num_threads(n);
    auto sim = strip::make(s, elastic());
    for (std::size_t i = 0; i < sim.particles().size(); ++i) sim.particles().v[i][0] = sim.particles().body[i] ? -3.0 : 3.0;
    sim.run_until(2.5 * 50 * kH / wave_speed());
    out.push_back(sim.particles());
  }
  omp_set_num_threads(threads);
  for (std::size_t i = 0; i < out[0].size(); ++i) {
    ASSERT_EQ(out[0].x[i], out[1].x[i]) << i;
    ASSERT_EQ(out[0].v[i], out[1].v[i]) << i;
  }
}

// Conduction runs on the grid's nodes, not the bodies' layers: two bars at rest, the lower 100 K
// warmer, conduct across their interface as one body, bit for bit the same with contact on and off
// (at rest the contact law has nothing to correct), and the upper bar's first row warms up (by
// 10.6 K in 100 steps; 0 if heat stayed in each body's layer).
TEST(Contact, HeatCrossesTheInterface) {
  strip::Setup s;
  s.h = kH;
  s.cells = 20;
  s.options.shape = mpm::ShapeKind::Gimp;
  s.options.heat_conduction = true;
  auto mat = elastic();
  mat.thermal.conductivity = 1e6;  // α = k/(ρc_v) = 0.41 m²/s: the heat crosses cells within 100 steps
  std::vector<mpm::Particles> out;
  for (bool on : {false, true}) {
    s.options.contact.enabled = on;
    auto sim = strip::make(s, mat);
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
      if (sim.particles().body[i] == 0) sim.particles().state[i].temperature += 100.0;
    for (int k = 0; k < 100; ++k) sim.step();
    out.push_back(sim.particles());
  }
  double first_row = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < out[0].size(); ++i) {
    ASSERT_EQ(out[0].state[i].temperature, out[1].state[i].temperature) << i;
    if (out[1].body[i] == 1 && out[1].x[i][1] < 0.5 * kH) first_row += out[1].state[i].temperature, ++n;
  }
  EXPECT_GT(first_row / n, mat.thermal.initial_temperature + 5.0);
  record("upper_first_row_rise_K", first_row / n - mat.thermal.initial_temperature);
}
