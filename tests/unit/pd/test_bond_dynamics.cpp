// PMB/LPS dynamics: momentum conservation, thread independence, the stable-step estimate and the
// diagnosis of an unstable step.
#include <gtest/gtest.h>
#include <omp.h>

#include <memory>

#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

struct Body {
  PointCloud cloud = lattice_cloud(3, {6, 6, 6}, 1e-3);
  Family family = build_family(cloud, 3.0002e-3, VolumeCorrection::linear);
};

std::unique_ptr<ForceModel> lps(const Body& b, CriticalStretch damage = {}) {
  return std::make_unique<LpsForce>(b.cloud, b.family, LpsModel{70e9, 26e9}, Influence(Influence::Kind::inverse), damage);
}

// Deterministic pseudo-random displacements and velocities.
void perturb(Simulation& sim) {
  for (std::size_t i = 0; i < sim.positions().size(); ++i) {
    const double a = std::sin(1.7 * i), b = std::cos(2.3 * i), c = std::sin(0.9 * i + 1.0);
    sim.positions()[i] += 2e-6 * Vec3(a, b, c);
    sim.velocities()[i] = 5.0 * Vec3(b, c, a);
  }
}

}  // namespace

TEST(BondDynamics, LpsConservesMomentum) {
  Body body;
  Simulation sim(body.cloud, body.family, lps(body), {2700.0});
  perturb(sim);
  const Vec3 p0 = sim.momentum();
  const double dt = 0.5 * sim.stable_step();
  for (int s = 0; s < 50; ++s) sim.step(dt);
  const double scale = 2700.0 * 216e-9 * 5.0;
  EXPECT_LT((sim.momentum() - p0).norm(), 1e-12 * scale);
}

TEST(BondDynamics, ResultsDoNotDependOnThreadCount) {
  Body body;
  std::vector<Vec3> y[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    Simulation sim(body.cloud, body.family, lps(body, {1e-3, 0.25}), {2700.0});
    perturb(sim);
    for (int s = 0; s < 20; ++s) sim.step(2e-8);
    y[t] = sim.positions();
  }
  omp_set_num_threads(1);
  for (std::size_t i = 0; i < y[0].size(); ++i) ASSERT_EQ(y[0][i], y[1][i]) << i;
}

// Velocity-Verlet on the estimate's step stays bounded; at 3× the estimate it blows up and the
// run stops with a RunError that says the step is unstable.
TEST(BondDynamics, StableStepEstimateAndUnstableStepDiagnosis) {
  Body body;
  for (double factor : {1.0, 3.0}) {
    Simulation sim(body.cloud, body.family,
                   std::make_unique<PmbForce>(body.cloud, body.family, PmbModel{1e22}, Influence(), CriticalStretch{}),
                   {2700.0});
    perturb(sim);
    const double dt = factor * sim.stable_step();
    if (factor == 1.0) {
      for (int s = 0; s < 400; ++s) sim.step(dt);
      EXPECT_LT(sim.kinetic_energy(), 1e3);
    } else {
      try {
        for (int s = 0; s < 4000; ++s) sim.step(dt);
        FAIL() << "no blow-up at 3x the stable step";
      } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("unstable"), std::string::npos) << e.what();
      }
    }
  }
}

// The damage state round-trips: a fresh force restored from saved_state() has the same broken
// bonds and critical stretches (its next forces are identical); a state without an array, with an
// array of the wrong size or stored as the wrong type is refused naming the array.
TEST(BondDynamics, DamageStateRoundTrips) {
  Body body;
  std::vector<Vec3> y = body.cloud.x, v(y.size(), Vec3::Zero()), f1, f2;
  for (std::size_t i = 0; i < y.size(); ++i) y[i] *= 1.0 + 2e-3 * std::sin(3.1 * static_cast<double>(i));
  LpsForce broken(body.cloud, body.family, LpsModel{70e9, 26e9}, Influence(Influence::Kind::inverse), {1e-3, 0.25});
  for (int k = 0; k < 2; ++k) broken.compute({y, v, 1e-9}, f1);
  ASSERT_LT(broken.intact_bonds(), body.family.bonds());
  ASSERT_GT(broken.intact_bonds(), 0u);
  LpsForce restored(body.cloud, body.family, LpsModel{70e9, 26e9}, Influence(Influence::Kind::inverse), {1e-3, 0.25});
  restored.restore_state(broken.saved_state());
  EXPECT_EQ(restored.intact_bonds(), broken.intact_bonds());
  EXPECT_EQ(restored.damage(), broken.damage());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] *= 1.0 + 1e-3 * std::cos(1.3 * static_cast<double>(i));
  broken.compute({y, v, 1e-9}, f1);
  restored.compute({y, v, 1e-9}, f2);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(restored.saved_state(), broken.saved_state());
  const ModelState saved = broken.saved_state();
  ASSERT_EQ(saved.size(), 2u);
  EXPECT_EQ(saved[0].name, "bond_intact");
  EXPECT_EQ(saved[0].counts.size(), body.family.bonds());
  EXPECT_EQ(saved[1].name, "critical_stretch");
  EXPECT_EQ(saved[1].reals.size(), y.size());
  const auto refusal = [&](ModelState state) {
    try {
      restored.restore_state(state);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal({saved[1]}).find("has no 'bond_intact'"), std::string::npos) << refusal({saved[1]});
  ModelState short_state = saved;
  short_state[1].reals.pop_back();
  EXPECT_NE(refusal(short_state).find("'critical_stretch' has"), std::string::npos) << refusal(short_state);
  ModelState real_flags = saved;
  real_flags[0].integer = false;
  EXPECT_NE(refusal(real_flags).find("stored as reals, expected integers"), std::string::npos) << refusal(real_flags);
}
