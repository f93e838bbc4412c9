// Time integration: NVE conserves energy and momentum; velocities start at exactly T with zero
// momentum; a run stopped at a checkpoint and resumed is bitwise the uninterrupted run; the
// thermostats reach their temperature; threads change results by round-off only.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"
#include <omp.h>

#include <filesystem>

#include "md_fixture.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/md/fixes/langevin.hpp"
#include "shockfield/md/fixes/nose_hoover.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/velocity.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

Simulation copper(std::array<int, 3> n, double temperature, double dt = 0.002) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, n, box, 63.55);
  create_velocities(atoms, temperature, 99);
  return Simulation(box, std::move(atoms), fixture::cu_eam(), dt, 1.0);
}

Vec3 momentum(const Simulation& s) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < s.atoms.nlocal; ++i) p += s.atoms.mass_of(i) * s.atoms.v[i];
  return p;
}

void run(Simulation& s, int steps) {
  for (int k = 0; k < steps; ++k) s.advance([](std::int64_t) { return false; });
}

}  // namespace

TEST(Velocity, CreatedAtExactTemperatureWithZeroMomentum) {
  Simulation s = copper({4, 4, 4}, 600.0);
  EXPECT_NEAR(s.thermo().temperature, 600.0, 1e-9);
  EXPECT_LT(momentum(s).norm(), 1e-10);
}

TEST(Dynamics, NveConservesEnergyAndMomentumOver10000Steps) {
  // 256 Cu atoms at 600 K, dt = 2 fs. Velocity Verlet has no secular drift: the total energy
  // fluctuates by O(dt²) (measured: 7e-5 eV/atom here; 1/4 of it at dt = 1 fs) around a
  // constant, plus a slow drift from the cubic-spline tables (measured: 1.0e-5 eV/atom over the
  // 20 ps). Bounds: fluctuation 2e-4 eV/atom, drift (mean of the last tenth minus mean of the
  // first tenth) 3e-5 eV/atom, against ~0.08 eV/atom of kinetic energy.
  Simulation s = copper({4, 4, 4}, 600.0);
  s.fixes.push_back(std::make_unique<FixNve>());
  s.setup(false);
  const double n = static_cast<double>(s.atoms.nlocal);
  std::vector<double> e;
  for (int k = 0; k < 10000; ++k) {
    run(s, 1);
    e.push_back((s.kinetic_energy() + s.forces.energy) / n);
  }
  const double e0 = e.front();
  double max_dev = 0, head = 0, tail = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    max_dev = std::max(max_dev, std::abs(e[k] - e0));
    if (k < 1000) head += e[k] / 1000;
    if (k >= 9000) tail += e[k] / 1000;
  }
  EXPECT_LT(max_dev, 2e-4);
  EXPECT_LT(std::abs(tail - head), 3e-5) << "head " << head << " tail " << tail;
  EXPECT_LT(momentum(s).norm(), 1e-9);
}

namespace {

template <class Make>
void expect_bitwise_restart(Make add_fixes, const std::string& name) {
  const auto file = shockfield::testing::scratch_path("shockfield_restart_" + name + ".h5");
  Simulation straight = copper({3, 3, 3}, 900.0);
  add_fixes(straight);
  straight.setup(false);
  run(straight, 120);

  Simulation first = copper({3, 3, 3}, 900.0);
  add_fixes(first);
  first.setup(false);
  run(first, 57);
  write_checkpoint(file, first, {0, 57});

  Simulation resumed = copper({3, 3, 3}, 10.0);  // different velocities: the checkpoint must win
  add_fixes(resumed);
  read_checkpoint(file, resumed);
  run(resumed, 63);
  ASSERT_EQ(resumed.step, straight.step);
  for (std::size_t i = 0; i < straight.atoms.nlocal; ++i) {
    ASSERT_EQ(resumed.atoms.x[i], straight.atoms.x[i]) << name << " atom " << i;
    ASSERT_EQ(resumed.atoms.v[i], straight.atoms.v[i]) << name << " atom " << i;
  }
  std::filesystem::remove(file);
}

}  // namespace

TEST(Restart, NveResumesBitwise) {
  expect_bitwise_restart([](Simulation& s) { s.fixes.push_back(std::make_unique<FixNve>()); }, "nve");
}

TEST(Restart, LangevinResumesBitwise) {
  expect_bitwise_restart([](Simulation& s) { s.fixes.push_back(std::make_unique<FixLangevin>(300.0, 0.1, 7)); },
                         "langevin");
}

TEST(Restart, NoseHooverResumesBitwise) {
  expect_bitwise_restart([](Simulation& s) { s.fixes.push_back(std::make_unique<FixNoseHoover>(300.0, 0.1)); },
                         "nvt");
}

TEST(Restart, FixedRebuildPolicyResumesBitwise) {
  // LAMMPS neigh_modify every 3 delay 2 check no: the step count since the last build is state.
  expect_bitwise_restart(
      [](Simulation& s) {
        s.neighbor_every = 3;
        s.neighbor_delay = 2;
        s.neighbor_check = false;
        s.fixes.push_back(std::make_unique<FixNve>());
      },
      "policy");
}

TEST(Neighbors, RebuildPolicyFollowsLammpsNeighModify) {
  Simulation s = copper({3, 3, 3}, 300.0);
  s.neighbor_every = 5;
  s.neighbor_check = false;
  s.fixes.push_back(std::make_unique<FixNve>());
  s.setup(false);
  run(s, 100);
  EXPECT_EQ(s.rebuilds, 1 + 100 / 5);  // setup + every 5th step, no distance check
  Simulation c = copper({3, 3, 3}, 300.0);
  c.neighbor_every = 1;
  c.neighbor_delay = 1000;
  c.fixes.push_back(std::make_unique<FixNve>());
  c.setup(false);
  run(c, 100);
  EXPECT_EQ(c.rebuilds, 1);  // the delay holds every rebuild back
}

TEST(Thermostat, LangevinAndNoseHooverReachTheirTemperature) {
  for (int kind = 0; kind < 2; ++kind) {
    Simulation s = copper({4, 4, 4}, 100.0);
    if (kind == 0) s.fixes.push_back(std::make_unique<FixLangevin>(500.0, 0.05, 11));
    else s.fixes.push_back(std::make_unique<FixNoseHoover>(500.0, 0.05));
    s.setup(false);
    run(s, 1500);
    double mean = 0;
    const int samples = 1500;
    for (int k = 0; k < samples; ++k) {
      run(s, 1);
      mean += s.thermo().temperature / samples;
    }
    // 256 atoms: canonical fluctuation of T is T·sqrt(2/(3N)) ≈ 25 K per sample; the mean over
    // 1500 correlated samples is within ~3%.
    EXPECT_NEAR(mean, 500.0, 20.0) << (kind == 0 ? "langevin" : "nose-hoover");
  }
}

TEST(Thermostat, NoseHooverConservesItsExtendedEnergy) {
  Simulation s = copper({4, 4, 4}, 300.0);
  s.fixes.push_back(std::make_unique<FixNoseHoover>(600.0, 0.1));
  s.setup(false);
  auto conserved = [&] { return s.kinetic_energy() + s.forces.energy - s.fixes[0]->energy_added(); };
  const double e0 = conserved();
  double max_dev = 0;
  for (int k = 0; k < 2000; ++k) {
    run(s, 1);
    max_dev = std::max(max_dev, std::abs(conserved() - e0));
  }
  // Same O(dt²) fluctuation as NVE (see above).
  EXPECT_LT(max_dev / static_cast<double>(s.atoms.nlocal), 2e-4);
}

TEST(Threads, ResultsDependOnThreadCountOnlyByRoundOff) {
  const int threads = omp_get_max_threads();
  std::vector<Vec3> x[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t == 0 ? 1 : 2);
    Simulation s = copper({4, 4, 4}, 600.0);
    s.fixes.push_back(std::make_unique<FixNve>());
    s.setup(false);
    run(s, 200);
    x[t] = s.atoms.x;
  }
  omp_set_num_threads(threads);
  double max_diff = 0;
  for (std::size_t i = 0; i < x[0].size(); ++i) max_diff = std::max(max_diff, (x[0][i] - x[1][i]).norm());
  EXPECT_LT(max_diff, 1e-8);
}
