// Loading regions (regions.hpp): a free body given a region velocity keeps its momentum to
// round-off; a held region moves exactly v·t; a 1D LPS bar whose end is pushed at constant v
// carries the analytic stress ρ c v behind the front, c = √((K + 4G/3)/ρ) (docs/theory/pd.md);
// a separate region is a body bonded to nothing outside it, which hits and leaves the rest through
// the contact force alone, with momentum and energy balances. A prescribed displacement ramped
// over a time launches the elastic pulse of the ramp rate into a 1D LPS bar, with the momentum and
// energy of that pulse; a linear velocity field (a uniform stretch given as velocity_formula)
// keeps its strain rate inside the body until the surface waves arrive; the same field from
// velocity_file gives the same run bit for bit. A region held in one component leaves the others
// free (its y momentum kept).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/precrack.hpp"
#include "shockfield/pd/regions.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

constexpr double kDensity = 8000.0, kBulk = 158e9, kShear = 73e9;  // steel

struct Body {
  Body(int dim, std::array<int, 3> counts, double spacing)
      : cloud(lattice_cloud(dim, counts, spacing)),
        family(build_family(cloud, 3.015 * spacing, VolumeCorrection::linear)) {}
  PointCloud cloud;
  Family family;
};

std::unique_ptr<LpsForce> lps(const Body& b, bool contact) {
  return std::make_unique<LpsForce>(b.cloud, b.family, LpsModel{kBulk, kShear, b.cloud.dim},
                                    Influence(Influence::Kind::inverse), CriticalStretch{},
                                    contact);
}

geometry::Region block(double xhi) {
  geometry::Region r;
  r.hi[0] = xhi;
  return r;
}

}  // namespace

// A 2D plate at rest but a disc of it at (30, −10) m/s (contact on): Σ ρV v is the disc's momentum
// at the start and stays so over 300 steps. Bond and contact forces are pairwise equal and
// opposite, so only round-off changes it: tolerance 1e-12 of the disc's momentum (measured 4e-16).
TEST(LoadRegions, FreeBodyKeepsItsMomentum) {
  constexpr double dx = 1e-3;
  const Body body(2, {20, 12, 1}, dx);
  Simulation sim(body.cloud, body.family, lps(body, true), {kDensity});
  geometry::Region disc;
  disc.shape = geometry::Region::Shape::sphere;
  disc.center = Vec3(6 * dx, 5 * dx, 0.0), disc.radius = 3.2 * dx;
  apply_regions(sim, {LoadRegion{disc, Loading::velocity, Vec3(30.0, -10.0, 0.0)}}, true);
  const std::size_t selected = points_in(disc, body.cloud).size();
  ASSERT_EQ(selected, 37u);  // the lattice points within 3.2 ΔX of a lattice point
  const Vec3 expected = kDensity * dx * dx * static_cast<double>(selected) * Vec3(30.0, -10.0, 0.0);
  EXPECT_LT((sim.momentum() - expected).norm(), 1e-14 * expected.norm());
  const double dt = 0.5 * sim.stable_step();
  for (int s = 0; s < 300; ++s) sim.step(dt);
  EXPECT_LT((sim.momentum() - expected).norm(), 1e-12 * expected.norm());
  EXPECT_GT((sim.velocities()[0]).norm(), 0.0);  // the wave left the disc
}

// The left edge of a 2D plate held at (5, 2) m/s for 300 steps: its points are at x + v·t (to the
// round-off of summing Δt·v to positions ~500 times |v·t|: measured ≤ 8e-13 of |v·t|, tolerance
// 1e-10), with velocity exactly v; the rest moves.
TEST(LoadRegions, PrescribedRegionMovesExactlyVt) {
  constexpr double dx = 1e-3;
  const Body body(2, {20, 12, 1}, dx);
  Simulation sim(body.cloud, body.family, lps(body, true), {kDensity});
  const Vec3 v(5.0, 2.0, 0.0);
  apply_regions(sim, {LoadRegion{block(2.5 * dx), Loading::prescribed_velocity, v}}, true);
  const double dt = 0.5 * sim.stable_step();
  for (int s = 0; s < 300; ++s) sim.step(dt);
  const double vt = v.norm() * sim.time();
  const std::vector<std::size_t> held = points_in(block(2.5 * dx), body.cloud);
  ASSERT_EQ(held.size(), 36u);
  for (std::size_t i : held) {
    EXPECT_LT((sim.positions()[i] - body.cloud.x[i] - v * sim.time()).norm(), 1e-10 * vt);
    EXPECT_EQ(sim.velocities()[i], v);
  }
  EXPECT_GT(sim.velocities()[10].norm(), 0.1);  // point (10, 0): reached by the wave
}

// A 1D LPS steel bar of 2000 points (ΔX = 50 µm, δ = 3.015ΔX) whose first 3 points are pushed
// into it at v = 10 m/s: behind the front the stress is ρ c v with c = √((K + 4G/3)/ρ) = 5649 m/s,
// i.e. 451.9 MPa. Measured two ways while the front crosses the bar: the rate of the bar's
// momentum (the force on the pusher per unit area, least squares over t in [0.2, 0.8]·T) and the
// mean strain between 0.2L and 0.5L at T (front at ~0.8L), times M = K + 4G/3. Measured −1e-7 and
// +5e-6 of ρcv; tolerance 1e-4: the 1D uniaxial LPS speed is exact for any δ (docs/theory/pd.md)
// and the step's dispersion ring averages out over the window; a wrong modulus (K alone: −21% in
// c) or a pusher that slips is far outside.
TEST(LoadRegions, PushedBarCarriesRhoCV) {
  constexpr double dx = 50e-6, v = 10.0;
  constexpr int n = 2000;
  const Body body(1, {n, 1, 1}, dx);
  Simulation sim(body.cloud, body.family, lps(body, false), {kDensity});
  apply_regions(sim, {LoadRegion{block(2.5 * dx), Loading::prescribed_velocity, Vec3(v, 0.0, 0.0)}},
                true);
  const double modulus = kBulk + 4.0 * kShear / 3.0, c = std::sqrt(modulus / kDensity);
  const double expected = kDensity * c * v;
  const double end = 0.8 * (n - 1) * dx / c, dt = 0.5 * sim.stable_step();
  double st = 0.0, sp = 0.0, stt = 0.0, stp = 0.0, count = 0.0;
  while (sim.time() < end) {
    sim.step(dt);
    if (sim.time() < 0.2 * end || sim.time() > 0.8 * end) continue;
    const double t = sim.time(), p = sim.momentum()[0];
    st += t, sp += p, stt += t * t, stp += t * p, count += 1.0;
  }
  const double rate = (count * stp - st * sp) / (count * stt - st * st);
  EXPECT_NEAR(rate, expected, 1e-4 * expected)
      << "momentum rate " << rate << " Pa, ρcv " << expected << " Pa";
  const auto u = [&](int i) { return sim.positions()[i][0] - body.cloud.x[i][0]; };
  const int a = n / 5, b = n / 2;
  const double strain = (u(b) - u(a)) / ((b - a) * dx);
  EXPECT_NEAR(-modulus * strain, expected, 1e-4 * expected) << "strain " << strain;
}

// The bonds between a separate disc and the rest of a 2D plate are exactly those with one end in
// the disc (counted directly), and the family without them has none left across its rim.
TEST(LoadRegions, SeparateBodyHasNoBondsOutside) {
  constexpr double dx = 1e-3;
  const Body body(2, {20, 12, 1}, dx);
  geometry::Region disc;
  disc.shape = geometry::Region::Shape::sphere;
  disc.center = Vec3(6 * dx, 5 * dx, 0.0), disc.radius = 3.2 * dx;
  const std::vector<unsigned char> between = bonds_between_bodies(
      body.cloud, body.family, {LoadRegion{disc, Loading::none, Vec3::Zero(), true}});
  std::size_t across = 0;
  for (std::size_t i = 0; i < body.cloud.size(); ++i)
    for (int b = body.family.begin(i); b < body.family.end(i); ++b)
      across += disc.match(body.cloud.x[i]) != disc.match(body.cloud.x[body.family.neighbor[b]]);
  EXPECT_GT(across, 300u);
  EXPECT_EQ(static_cast<std::size_t>(std::count(between.begin(), between.end(), 1)), across);
  const Family kept = without_bonds(body.family, between);
  for (std::size_t i = 0; i < body.cloud.size(); ++i)
    for (int b = kept.begin(i); b < kept.end(i); ++b)
      EXPECT_EQ(disc.match(body.cloud.x[i]), disc.match(body.cloud.x[kept.neighbor[b]]));
}

// A 3D PMB block 12×4×4 (ΔX = 0.5 mm, δ = 2.6ΔX, contact on, no breaking) whose left half is a
// separate body at 50 m/s: it hits the right half, which it is not bonded to, and the halves come
// apart again, the right one carrying most of the momentum; the same block with its halves bonded
// stays whole. Momentum is conserved to round-off (tolerance 1e-12 of its value); kinetic + bond +
// contact energy within 2e-3 of the impact energy, the integrator's error at 1/8 of the stable step
// (as the contact bounce of test_contact.cpp; measured 2.4e-4). Measured: the right half ends with
// 0.94 of the momentum and the halves 9.7ΔX apart; bonded, 1.0ΔX.
TEST(LoadRegions, SeparateBodyBouncesOffThroughContactOnly) {
  constexpr double dx = 5e-4, v = 50.0, bulk = 14.9e9, density = 2200.0;
  const PointCloud cloud = lattice_cloud(3, {12, 4, 4}, dx);
  const Family bonded = build_family(cloud, 2.6 * dx, VolumeCorrection::linear);
  const LoadRegion left{block(5.5 * dx), Loading::velocity, Vec3(v, 0.0, 0.0), true};
  const Family apart = without_bonds(bonded, bonds_between_bodies(cloud, bonded, {left}));
  const PmbModel pmb{LpsModel{bulk, 0.6 * bulk, 3}.contact_micromodulus(2.6 * dx)};
  double gap[2], right_momentum[2];  // [separate]
  for (int separate = 0; separate < 2; ++separate) {
    const Family& family = separate ? apart : bonded;
    auto model =
        std::make_unique<PmbForce>(cloud, family, pmb, Influence(), CriticalStretch{}, true);
    PmbForce& force = *model;
    Simulation sim(cloud, family, std::move(model), {density});
    apply_regions(sim, {left}, true);
    const Vec3 p0 = sim.momentum();
    const double e0 = sim.kinetic_energy(), dt = 0.125 * sim.stable_step();
    double drift = 0.0;
    for (int s = 0; s < 6000; ++s) {
      sim.step(dt);
      drift = std::max(
          drift, std::abs(sim.kinetic_energy() + force.potential_energy(sim.positions()) - e0));
    }
    EXPECT_LT((sim.momentum() - p0).norm(), 1e-12 * p0.norm());
    EXPECT_LT(drift, 2e-3 * e0) << "separate " << separate;
    double right = 0.0, right_edge = std::numeric_limits<double>::infinity(),
           left_edge = -right_edge;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      if (left.shape.match(cloud.x[i])) {
        left_edge = std::max(left_edge, sim.positions()[i][0]);
      } else {
        right += density * cloud.volume[i] * sim.velocities()[i][0];
        right_edge = std::min(right_edge, sim.positions()[i][0]);
      }
    }
    gap[separate] = (right_edge - left_edge) / dx, right_momentum[separate] = right / p0[0];
  }
  EXPECT_GT(right_momentum[1], 0.8);  // the hit half took most of the momentum...
  EXPECT_GT(gap[1], 3.0);             // ...and left the striker behind
  EXPECT_LT(gap[0], 1.5);             // bonded halves stay together
}

// A 1D LPS steel bar of 1000 points (ΔX = 50 µm) whose first 3 points are displaced by
// u(t) = U·min(t/T, 1), U = 10 m/s · T, T = 0.3 L/c: the held points sit at x + u(t) at every
// step (measured 5e-16 of U, tolerance 1e-12: the round-off of x + u) with velocity U/T, then 0.
// They push a pulse of length c·T and particle velocity v = U/T into the bar,
// c = √((K + 4G/3)/ρ) (exact for the 1D LPS bar: docs/theory/pd.md). Analytic, per unit area:
// the momentum grows at ρcv while the ramp lasts (measured −1.8e-6, tolerance 1e-4: the ramp's
// start rings, the window averages it) and is ρcU after it (the held end is then at rest and
// unstrained behind the pulse; measured 8.9e-6, tolerance 1e-3). Energy: kinetic + strain energy
// equal the work Σ F·Δu the held end did on the body (F = −Σ_held V_i L_i; measured 1.4e-4,
// tolerance 1e-3, the trapezoid rule's and the integrator's error), which is ρ c v²·T to within
// the time the reaction takes to build up as the front crosses the first horizon (~δ/(cT) = 1e-2;
// measured −2.2e-3, tolerance 5e-3; the same at a quarter of the step). A ramp twice too fast or
// a held point that slips is far outside.
TEST(RegionLoadings, RampedDisplacementLaunchesThePulseOfItsRate) {
  constexpr double dx = 50e-6, v = 10.0;
  constexpr int n = 1000;
  const Body bar(1, {n, 1, 1}, dx);
  auto model = lps(bar, false);
  LpsForce& force = *model;
  Simulation sim(bar.cloud, bar.family, std::move(model), {kDensity});
  const double modulus = kBulk + 4.0 * kShear / 3.0, c = std::sqrt(modulus / kDensity),
               length = (n - 1) * dx;
  LoadRegion end{block(2.5 * dx), Loading::prescribed_displacement};
  end.ramp_time = 0.3 * length / c;
  end.displacement = Vec3(v * end.ramp_time, 0.0, 0.0);
  // The reaction of the held points on the body, −Σ_held V_i L_i, before the region drops it.
  double reaction = 0.0;
  sim.add_hook(Simulation::Stage::after_force, [&reaction](Simulation& s) {
    reaction = 0.0;
    for (int i = 0; i < 3; ++i) reaction -= s.cloud().volume[i] * s.force_density()[i][0];
  });
  apply_regions(sim, {end}, true);
  sim.setup();
  const double dt = 0.5 * sim.stable_step(), stop = 0.8 * length / c, big_u = end.displacement[0];
  double work = 0.0;  // Σ ½(F_n + F_{n+1})·(u_{n+1} − u_n) of the held end
  double st = 0.0, sp = 0.0, stt = 0.0, stp = 0.0, count = 0.0, worst = 0.0;
  while (sim.time() < stop) {
    const double reaction_before = reaction, u_before = sim.positions()[0][0];
    sim.step(dt);
    work += 0.5 * (reaction_before + reaction) * (sim.positions()[0][0] - u_before);
    const double t = sim.time();
    for (int i = 0; i < 3; ++i) {
      worst = std::max(worst, std::abs(sim.positions()[i][0] - bar.cloud.x[i][0] -
                                       big_u * std::min(t / end.ramp_time, 1.0)));
      ASSERT_EQ(sim.velocities()[i][0], t < end.ramp_time ? v : 0.0) << "step " << sim.step_count();
    }
    if (t < 0.1 * end.ramp_time || t > 0.9 * end.ramp_time) continue;
    const double p = sim.momentum()[0];
    st += t, sp += p, stt += t * t, stp += t * p, count += 1.0;
  }
  EXPECT_LT(worst, 1e-12 * big_u);
  const double rate = (count * stp - st * sp) / (count * stt - st * st), impedance = kDensity * c;
  EXPECT_NEAR(rate, impedance * v, 1e-4 * impedance * v) << "momentum rate while ramping";
  EXPECT_NEAR(sim.momentum()[0], impedance * big_u, 1e-3 * impedance * big_u)
      << "momentum of the pulse";
  const double energy = sim.kinetic_energy() + force.potential_energy(sim.positions());
  EXPECT_NEAR(energy, work, 1e-3 * work) << "kinetic + strain energy against the boundary's work";
  const double expected = impedance * v * v * end.ramp_time;
  EXPECT_NEAR(energy, expected, 5e-3 * expected) << "kinetic + strain energy of the pulse";
}

// A held displacement (ramp_time 0) is in place from t = 0: the setup's forces are those of the
// displaced end, and the points stay there with zero velocity.
TEST(RegionLoadings, HeldDisplacementIsInPlaceFromTheStart) {
  const Body bar(1, {100, 1, 1}, 50e-6);
  Simulation sim(bar.cloud, bar.family, lps(bar, false), {kDensity});
  LoadRegion end{block(2.5 * 50e-6), Loading::prescribed_displacement};
  end.displacement = Vec3(1e-7, 0.0, 0.0);
  apply_regions(sim, {end}, true);
  sim.setup();
  EXPECT_EQ(sim.positions()[0][0], bar.cloud.x[0][0] + 1e-7);
  EXPECT_GT(std::abs(sim.force_density()[3][0]),
            0.0);  // the first free point feels the compressed end
  for (int s = 0; s < 20; ++s) sim.step(0.5 * sim.stable_step());
  EXPECT_EQ(sim.positions()[2][0], bar.cloud.x[2][0] + 1e-7);
  EXPECT_EQ(sim.velocities()[2][0], 0.0);
  EXPECT_GT(sim.velocities()[3][0], 0.0);
}

// A 1D LPS bar of 400 points (ΔX = 50 µm) starting in uniform stretch, v = ε̇ (x − L/2) from
// velocity_formula, ε̇ = 1e3 /s: forces vanish where a point's family and its neighbours' are
// whole, so the middle keeps the velocity field until the surface waves (c·t = 2.5 mm = 50ΔX
// after 100 steps, plus two horizons) arrive: its velocities are ε̇ (x − L/2) (measured 7.6e-11
// of ε̇L/2, tolerance 1e-9) and its strain ε̇·t (measured 3.5e-13, tolerance 1e-10): the
// round-off of bond forces that cancel, over 100 steps. A formula read for the wrong coordinate
// or sign is far outside.
TEST(RegionLoadings, LinearVelocityFieldKeepsItsStrainRate) {
  constexpr double dx = 50e-6, rate = 1e3;
  constexpr int n = 400;
  const Body bar(1, {n, 1, 1}, dx);
  Simulation sim(bar.cloud, bar.family, lps(bar, false), {kDensity});
  const double middle = 0.5 * (n - 1) * dx;
  const Config table = Config::parse(
      fmt::format("shape = \"block\"\nvelocity_formula = [\"{} * (x - {})\"]", rate, middle));
  const LoadRegion field = read_load_region(table, 1, BodyPoints{{n, 1, 1}, dx});
  apply_regions(sim, {field}, true);
  for (int s = 0; s < 100; ++s) sim.step(0.5 * sim.stable_step());
  ASSERT_GT(sim.velocities()[0][0], -rate * middle * 0.99);  // the surface has been slowed
  const int a = 140, b = 260;
  for (int i = a; i <= b; ++i)
    EXPECT_NEAR(sim.velocities()[i][0], rate * (bar.cloud.x[i][0] - middle), 1e-9 * rate * middle)
        << i;
  const auto u = [&](int i) { return sim.positions()[i][0] - bar.cloud.x[i][0]; };
  const double strain = (u(b) - u(a)) / ((b - a) * dx);
  EXPECT_NEAR(strain, rate * sim.time(), 1e-10 * rate * sim.time());
}

// The velocity field of a 2D plate's disc from velocity_formula, and the same numbers written to a
// velocity_file (17 significant digits: the doubles exactly), run 100 steps alike bit for bit.
TEST(RegionLoadings, VelocityFileGivesTheFormulaRunBitwise) {
  constexpr double dx = 1e-3;
  const std::array<int, 3> counts{20, 12, 1};
  const Body plate(2, counts, dx);
  const std::string shape = "shape = \"sphere\"\ncenter = [6e-3, 5e-3, 0.0]\nradius = 3.2e-3\n";
  const Config by_formula =
      Config::parse(shape + "velocity_formula = [\"300*sin(pi*x/0.02)\", \"-50*y/0.012 + 2^-1\"]");
  const LoadRegion formula = read_load_region(by_formula, 2, BodyPoints{counts, dx});
  const std::filesystem::path file =
      shockfield::testing::scratch_path("pd_region_velocity_file.csv");
  {
    std::ofstream out(file);
    out << "x,y,z,vx,vy,vz\n";
    for (std::size_t i : points_in(formula.shape, plate.cloud)) {
      const Vec3& x = plate.cloud.x[i];
      out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},0\n", x[0], x[1], x[2],
                         formula.formula[0](x), formula.formula[1](x));
    }
  }
  const Config by_file =
      Config::parse(shape + fmt::format("velocity_file = \"{}\"", file.string()));
  const LoadRegion from_file = read_load_region(by_file, 2, BodyPoints{counts, dx});
  std::filesystem::remove(file);
  ASSERT_EQ(from_file.point_velocity.size(), 37u);
  Simulation a(plate.cloud, plate.family, lps(plate, false), {kDensity});
  Simulation b(plate.cloud, plate.family, lps(plate, false), {kDensity});
  apply_regions(a, {formula}, true);
  apply_regions(b, {from_file}, true);
  const double dt = 0.5 * a.stable_step();
  for (int s = 0; s < 100; ++s) a.step(dt), b.step(dt);
  EXPECT_GT(a.velocities()[0].norm(), 0.0);
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_EQ(a.velocities(), b.velocities());
}

// A body force b = σ/ΔX on the top row of a 2D LPS plate (a traction σ = 2 MPa on its top edge,
// as the crack-branching plates are loaded): the plate's momentum is the impulse Σ_top V b t,
// y-ward (the bond forces are pairwise equal and opposite, so only round-off changes it further:
// tolerance 1e-12), and the top moves away from the bottom. A body force applied twice, or on
// the wrong points, is far outside.
TEST(LoadRegions, BodyForceOnAnEdgeGivesItsImpulse) {
  constexpr double dx = 1e-3, sigma = 2e6;
  const Body body(2, {20, 12, 1}, dx);
  Simulation sim(body.cloud, body.family, lps(body, false), {kDensity});
  geometry::Region top;
  top.lo[1] = 10.5 * dx;
  LoadRegion pull(top, Loading::none);
  pull.body_force = Vec3(0.0, sigma / dx, 0.0);
  apply_regions(sim, {pull}, true);
  const double dt = 0.5 * sim.stable_step();
  for (int s = 0; s < 200; ++s) sim.step(dt);
  const double impulse = 20.0 * dx * dx * (sigma / dx) * sim.time();  // top row: 20 points of V = ΔX²
  EXPECT_NEAR(sim.momentum()[1], impulse, 1e-12 * impulse);
  EXPECT_LT(std::abs(sim.momentum()[0]), 1e-12 * impulse);
  const std::size_t corner = body.cloud.size() - 1;  // (19, 11): top right
  // Stretched: σ/M ~ 8e-6 where the wave has passed (measured 1e-5 over the height).
  EXPECT_GT(sim.positions()[corner][1] - sim.positions()[19][1], 11.0 * dx * (1.0 + 1e-6));
}

// A held component leaves the others free (`components`): a 2D plate moving at v_y = 3 m/s whose
// left edge is held in x only (at v_x = 5 m/s, or displaced by U_x = 1 µm) keeps its y momentum
// Σ ρV v_y to round-off (the hold exerts no y reaction; bond and contact forces are pairwise
// equal and opposite: tolerance 1e-12, as FreeBodyKeepsItsMomentum), while its edge sits exactly at
// x + v_x·t (or x + U_x) with v_x held and moves in y with the body. Holding every component
// instead would stop the edge in y (v_y = 0) and change the momentum by the edge's 3 m/s.
TEST(RegionLoadings, HeldComponentLeavesTheOthersFree) {
  constexpr double dx = 1e-3;
  const Body body(2, {20, 12, 1}, dx);
  const std::vector<std::size_t> edge = points_in(block(2.5 * dx), body.cloud);
  ASSERT_EQ(edge.size(), 36u);
  for (const Loading loading : {Loading::prescribed_velocity, Loading::prescribed_displacement}) {
    Simulation sim(body.cloud, body.family, lps(body, true), {kDensity});
    LoadRegion held(block(2.5 * dx), loading, Vec3(5.0, 0.0, 0.0));
    held.displacement = Vec3(1e-6, 0.0, 0.0);
    held.held_components = {true, false, false};
    apply_regions(sim, {LoadRegion(block(1.0), Loading::velocity, Vec3(0.0, 3.0, 0.0)), held}, true);
    const auto momentum_y = [&] {
      double p = 0.0;
      for (std::size_t i = 0; i < body.cloud.size(); ++i) p += kDensity * body.cloud.volume[i] * sim.velocities()[i][1];
      return p;
    };
    const double p0 = momentum_y();
    const double dt = 0.5 * sim.stable_step();
    for (int s = 0; s < 300; ++s) sim.step(dt);
    EXPECT_NEAR(momentum_y(), p0, 1e-12 * std::abs(p0));
    for (std::size_t i : edge) {
      const double x = body.cloud.x[i][0] + (loading == Loading::prescribed_velocity ? 5.0 * sim.time() : 1e-6);
      EXPECT_NEAR(sim.positions()[i][0], x, 1e-10 * dx);
      EXPECT_EQ(sim.velocities()[i][0], loading == Loading::prescribed_velocity ? 5.0 : 0.0);
      EXPECT_GT(sim.positions()[i][1] - body.cloud.x[i][1], 0.5 * 3.0 * sim.time());  // carried in y
    }
  }
}
