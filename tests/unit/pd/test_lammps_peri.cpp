// PMB and LPS against LAMMPS peri/pmb and peri/lps (tests/fixtures/lammps_peri, regenerate.sh):
// an 8×8×8 simple-cubic lattice, lc = 0.5 mm, δ = 3.0002·lc, randomly displaced by up to
// 0.2 µm and pulled apart at ±10 m/s so that bonds break (critical stretch 0.002, α = 0.25).
#include <gtest/gtest.h>

#include <memory>

#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

constexpr double kSpacing = 0.0005, kHorizon = 0.0015001, kDensity = 2200.0, kDt = 1.0e-7;

struct Fixture {
  PointCloud cloud;
  Family family;
  std::vector<io::DumpFrame> frames;
};

Fixture load(const std::string& style) {
  Fixture fx;
  const auto ref = io::read_dump("fixtures/lammps_peri/" + style + "_reference.dump").front();
  fx.cloud.dim = 3;
  fx.cloud.spacing = kSpacing;
  fx.cloud.x = ref.positions();
  fx.cloud.volume.assign(fx.cloud.x.size(), 1.25e-10);
  fx.family = build_family(fx.cloud, kHorizon, VolumeCorrection::linear);
  fx.frames = io::read_dump("fixtures/lammps_peri/" + style + "_trajectory.dump");
  return fx;
}

std::unique_ptr<ForceModel> make_model(const std::string& style, const Fixture& fx) {
  const CriticalStretch damage{0.0020, 0.25};
  if (style == "pmb") return std::make_unique<PmbForce>(fx.cloud, fx.family, PmbModel{1.6863e22}, Influence(), damage);
  return std::make_unique<LpsForce>(fx.cloud, fx.family, LpsModel{14.9e9, 8.94e9},
                                    Influence(Influence::Kind::inverse), damage);
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

// Forces at step 0 agree to round-off (1e-12 of the largest force density: the sums run in a
// different order), then the trajectory over 200 steps with bond breaking: positions within
// 1e-9 of the lattice constant, velocities within 1e-6 of their largest value, damage per point
// within 1e-9 (the same bonds broke at the same steps).
void cross_check(const std::string& style) {
  Fixture fx = load(style);
  ASSERT_EQ(fx.cloud.size(), 512u);
  ASSERT_EQ(fx.frames.front().timestep, 0);
  Simulation sim(fx.cloud, fx.family, make_model(style, fx), {kDensity});
  sim.setup();  // LAMMPS's "run 1" of the resting lattice: s0 = s00
  sim.positions() = fx.frames.front().positions();
  sim.velocities() = vectors(fx.frames.front(), "vx", "vy", "vz");
  sim.setup();  // the second run's setup force evaluation
  const auto f0 = vectors(fx.frames.front(), "fx", "fy", "fz");
  EXPECT_LT(max_diff(sim.force_density(), f0), 1e-12 * max_abs(f0)) << style << " forces at step 0";

  for (std::size_t k = 1; k < fx.frames.size(); ++k) {
    const auto& frame = fx.frames[k];
    while (sim.step_count() < frame.timestep) sim.step(kDt);
    const auto v = vectors(frame, "vx", "vy", "vz");
    EXPECT_LT(max_diff(sim.positions(), frame.positions()), 1e-9 * kSpacing) << style << " step " << frame.timestep;
    EXPECT_LT(max_diff(sim.velocities(), v), 1e-6 * max_abs(v)) << style << " step " << frame.timestep;
    const auto phi = sim.model().damage();
    const auto& ref = frame.column("c_dmg");
    double dphi = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) dphi = std::max(dphi, std::abs(phi[i] - ref[i]));
    EXPECT_LT(dphi, 1e-9) << style << " damage at step " << frame.timestep;
  }
}

}  // namespace

TEST(LammpsPeri, PmbMatchesPeriPmb) { cross_check("pmb"); }
TEST(LammpsPeri, LpsMatchesPeriLps) { cross_check("lps"); }
