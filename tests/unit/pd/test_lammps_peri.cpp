// PMB and LPS against LAMMPS peri/pmb and peri/lps (tests/fixtures/lammps_peri, regenerate.sh):
// - in.peri: an 8×8×8 simple-cubic lattice, lc = 0.5 mm, δ = 3.0002·lc, randomly displaced by up
//   to 0.2 µm and pulled apart at ±10 m/s so that bonds break (critical stretch 0.002, α = 0.25);
// - in.block: the block of issue 17, 20×8×8 points, δ = 2.6·lc, the left half hitting the right
//   half at 100 m/s, 500 steps: the block shatters and LAMMPS's short-range contact force acts on
//   up to 40 pairs at a time (contact.hpp), which shockfield applies with the same reach and
//   stiffness;
// - in.bounce: two 4×4×4 blocks, no bond between them, meeting at ±50 m/s: only the contact force
//   turns them around (300 steps).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

constexpr double kSpacing = 0.0005, kDensity = 2200.0, kDt = 1.0e-7;

// One LAMMPS input of the fixtures: its dump prefix, horizon, PMB micromodulus and critical stretch
// (LPS: K = 14.9 GPa, G = 8.94 GPa in all).
struct Input {
  std::string prefix;
  double horizon, micromodulus, s00;
};
const Input kPeri{"", 0.0015001, 1.6863e22, 0.002};
const Input kBlock{"block_", 0.0013, 2.989065910664636e22, 0.002};
const Input kBounce{"bounce_", 0.0013, 2.989065910664636e22, 0.05};

struct Fixture {
  PointCloud cloud;
  Family family;
  std::vector<io::DumpFrame> frames;
};

Fixture load(const Input& in, const std::string& style) {
  Fixture fx;
  const std::string base = "fixtures/lammps_peri/" + in.prefix + style;
  const auto ref = io::read_dump(base + "_reference.dump").front();
  fx.cloud.dim = 3;
  fx.cloud.spacing = kSpacing;
  fx.cloud.x = ref.positions();
  fx.cloud.volume.assign(fx.cloud.x.size(), 1.25e-10);
  fx.family = build_family(fx.cloud, in.horizon, VolumeCorrection::linear);
  fx.frames = io::read_dump(base + "_trajectory.dump");
  return fx;
}

std::unique_ptr<ForceModel> make_model(const Input& in, const std::string& style, const Fixture& fx, bool contact) {
  const CriticalStretch damage{in.s00, 0.25};
  if (style == "pmb")
    return std::make_unique<PmbForce>(fx.cloud, fx.family, PmbModel{in.micromodulus}, Influence(), damage, contact);
  return std::make_unique<LpsForce>(fx.cloud, fx.family, LpsModel{14.9e9, 8.94e9},
                                    Influence(Influence::Kind::inverse), damage, contact);
}

std::vector<Vec3> vectors(const io::DumpFrame& f, const char* a, const char* b, const char* c) {
  const auto &x = f.column(a), &y = f.column(b), &z = f.column(c);
  std::vector<Vec3> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = Vec3(x[i], y[i], z[i]);
  return out;
}

double max_diff(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).cwiseAbs().maxCoeff());
  return d;
}

double max_abs(const std::vector<Vec3>& a) {
  double d = 0.0;
  for (const Vec3& v : a) d = std::max(d, v.cwiseAbs().maxCoeff());
  return d;
}

template <class Model>
std::size_t pairs_in_contact(Simulation& sim) {
  auto* force = dynamic_cast<BondForce<Model>*>(&sim.model());
  return force && force->contact() ? force->contact()->active_pairs(sim.positions()) : 0;
}

// Per frame after step 0: the largest differences from LAMMPS (positions in units of the lattice
// constant, velocities relative to the frame's largest, damage), the largest position difference
// between this run and a twin whose initial positions differ by 1e-14 lc (a few ulp: how far
// round-off alone carries), and the most pairs in contact at a step since the previous frame.
struct Frame {
  long long step;
  double position, velocity, damage, twin;
  std::size_t contact_pairs;
};

std::vector<Frame> compare(const Input& in, const std::string& style, bool contact, std::size_t points) {
  Fixture fx = load(in, style);
  EXPECT_EQ(fx.cloud.size(), points);
  EXPECT_EQ(fx.frames.front().timestep, 0);
  const auto start = [&](Simulation& sim, double shift) {
    sim.setup();  // LAMMPS's "run 1" of the resting lattice: s0 = s00
    sim.positions() = fx.frames.front().positions();
    for (std::size_t i = 0; i < sim.positions().size(); ++i)
      sim.positions()[i] += shift * kSpacing * Vec3(std::sin(1.0 * i), std::cos(1.0 * i), std::sin(3.0 * i));
    sim.velocities() = vectors(fx.frames.front(), "vx", "vy", "vz");
    sim.setup();  // the second run's setup force evaluation
  };
  Simulation sim(fx.cloud, fx.family, make_model(in, style, fx, contact), {kDensity});
  Simulation twin(fx.cloud, fx.family, make_model(in, style, fx, contact), {kDensity});
  start(sim, 0.0);
  start(twin, 1e-14);
  if (fx.frames.front().has("fx")) {
    // Forces at step 0 agree to round-off (the sums run in a different order).
    const auto f0 = vectors(fx.frames.front(), "fx", "fy", "fz");
    EXPECT_LT(max_diff(sim.force_density(), f0), 1e-12 * max_abs(f0)) << style << " forces at step 0";
  }
  std::vector<Frame> frames;
  for (std::size_t k = 1; k < fx.frames.size(); ++k) {
    const auto& frame = fx.frames[k];
    std::size_t pairs = 0;  // most pairs in contact at a step since the last frame
    while (sim.step_count() < frame.timestep) {
      sim.step(kDt), twin.step(kDt);
      pairs = std::max(pairs, pairs_in_contact<PmbModel>(sim) + pairs_in_contact<LpsModel>(sim));
    }
    const auto v = vectors(frame, "vx", "vy", "vz");
    const auto phi = sim.model().damage();
    const auto& ref = frame.column("c_dmg");
    double damage = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) damage = std::max(damage, std::abs(phi[i] - ref[i]));
    frames.push_back({sim.step_count(), max_diff(sim.positions(), frame.positions()) / kSpacing,
                      max_diff(sim.velocities(), v) / max_abs(v), damage,
                      max_diff(sim.positions(), twin.positions()) / kSpacing, pairs});
  }
  return frames;
}

std::size_t most_pairs(const std::vector<Frame>& frames) {
  std::size_t n = 0;
  for (const Frame& f : frames) n = std::max(n, f.contact_pairs);
  return n;
}

// Round-off apart, the same trajectory: damage per point within 1e-9 at every frame (the same
// bonds broke at the same steps); positions within 1e-9 of the lattice constant and velocities
// within 1e-6 of their largest value up to step `exact_until`, and after it no further from LAMMPS
// than twice the twin is from this run (when fragments collide, differences of a few ulp grow
// ~30-fold per 100 steps whoever makes them; a model difference, e.g. a reach of 1.3 instead of
// 1.35 lc, is at once ~1e-3 lc).
void expect_same(const std::vector<Frame>& frames, const std::string& what, long long exact_until) {
  for (const Frame& f : frames) {
    std::printf("%s step %lld: from LAMMPS positions %.3g lc, velocities %.3g, damage %.3g; twin %.3g lc; %zu pairs "
                "in contact\n",
                what.c_str(), f.step, f.position, f.velocity, f.damage, f.twin, f.contact_pairs);
    EXPECT_LT(f.damage, 1e-9) << what << " step " << f.step;
    if (f.step <= exact_until) {
      EXPECT_LT(f.position, 1e-9) << what << " step " << f.step;
      EXPECT_LT(f.velocity, 1e-6) << what << " step " << f.step;
    } else {
      EXPECT_LT(f.position, 2.0 * f.twin) << what << " step " << f.step;
    }
  }
}

}  // namespace

// in.peri, 200 steps: the bodies pull apart, so no pair comes into contact.
TEST(LammpsPeri, PmbMatchesPeriPmb) { expect_same(compare(kPeri, "pmb", true, 512), "pmb 8x8x8", 200); }
TEST(LammpsPeri, LpsMatchesPeriLps) { expect_same(compare(kPeri, "lps", true, 512), "lps 8x8x8", 200); }

// in.bounce, 300 steps: the blocks meet, push each other back through contact alone and part; with
// contact the same trajectory throughout; without it they would pass through each other.
void bounce(const std::string& style) {
  const std::vector<Frame> with = compare(kBounce, style, true, 128);
  expect_same(with, style + " bounce", 300);
  EXPECT_GE(most_pairs(with), 8u) << style;
  EXPECT_EQ(with.back().contact_pairs, 0u) << style << ": in contact during the last 50 steps";
  EXPECT_GT(compare(kBounce, style, false, 128).back().position, 1.0) << style << " without contact";
}
TEST(LammpsPeri, PmbBounceMatchesPeriPmb) { bounce("pmb"); }
TEST(LammpsPeri, LpsBounceMatchesPeriLps) { bounce("lps"); }

// in.block, 500 steps: the block shatters and its fragments collide; with contact the same
// trajectory, exact to step 200 and round-off-amplified after, and contact did act (at least 10
// pairs at some frame). Without the contact force the runs part: the positions differ by more
// than 1% of the lattice constant (issue 17 saw 4% by step 200), so the test can tell.
void block(const std::string& style) {
  const std::vector<Frame> with = compare(kBlock, style, true, 1280);
  expect_same(with, style + " block", 200);
  EXPECT_GE(most_pairs(with), 10u) << style;
  const std::vector<Frame> without = compare(kBlock, style, false, 1280);
  EXPECT_GT(without.back().position, 1e-2) << style << " without contact";
  std::printf("%s block without contact: positions differ by %.3g lc at step %lld\n", style.c_str(),
              without.back().position, without.back().step);
}
TEST(LammpsPeri, PmbBlockWithContactMatchesPeriPmb) { block("pmb"); }
TEST(LammpsPeri, LpsBlockWithContactMatchesPeriLps) { block("lps"); }
