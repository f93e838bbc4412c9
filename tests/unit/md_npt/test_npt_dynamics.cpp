// NPT integration: the extended energy econserved = K + U − energy_added (MTK eq. 2.11) is
// conserved; a run stopped at a checkpoint and resumed is bitwise the uninterrupted one; a
// barostat on z only leaves x and y alone; iso keeps a cubic box cubic.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cstdio>
#include <filesystem>

#include "npt_fixture.hpp"
#include "shockfield/md/checkpoint.hpp"

using namespace shockfield;
using namespace shockfield::md;
using namespace shockfield::md::npt_test;

namespace {

/// Largest |econserved − econserved₀| per atom over `steps` steps.
double max_energy_deviation(Simulation& sim, int steps) {
  const double e0 = econserved(sim);
  double dev = 0;
  for (int k = 0; k < steps; ++k) {
    run(sim, 1);
    dev = std::max(dev, std::abs(econserved(sim) - e0));
  }
  return dev / static_cast<double>(sim.atoms.nlocal);
}

}  // namespace

TEST(NptDynamics, ExtendedEnergyIsConserved) {
  // 256 atoms from the 0 K lattice at 300 K: far from equilibrium, so the box, both chains and the
  // P(V − V₀) term all move (at 10 GPa the box shrinks by ~7% in volume). Velocity Verlet keeps
  // the extended energy to O(dt²) without drift: NVE in tests/unit/md fluctuates by 7e-5
  // eV/atom at 600 K; bound 2e-4 eV/atom against ~0.04 eV/atom of kinetic energy and, at 10
  // GPa, ~0.45 eV/atom of P ΔV work.
  struct Case {
    const char* name;
    NptSettings s;
  };
  for (const Case& c : {Case{"iso 0 bar", settings(0.0, true)}, Case{"aniso 10 GPa", settings(1e5, false)},
                        Case{"z only 10 GPa", settings(1e5, false, {false, false, true})}}) {
    Simulation sim = copper_npt(4, 3.615, 300.0, c.s);
    const double v0 = sim.box.volume();
    const double dev = max_energy_deviation(sim, 2000);
    std::printf("%s: max |econserved - econserved0| = %.2e eV/atom, V/V0 = %.4f\n", c.name, dev, sim.box.volume() / v0);
    EXPECT_LT(dev, 2e-4) << c.name;
    if (c.s.pressure > 0) {
      EXPECT_LT(sim.box.volume(), 0.97 * v0) << c.name << ": the box did not respond";
    }
  }
}

TEST(NptDynamics, ResumesBitwiseFromACheckpoint) {
  const auto file = shockfield::testing::scratch_path("shockfield_restart_npt.h5");
  for (bool iso : {true, false}) {
    const NptSettings s = settings(2e4, iso);
    Simulation straight = copper_npt(3, 3.615, 600.0, s);
    run(straight, 120);

    Simulation first = copper_npt(3, 3.615, 600.0, s);
    run(first, 57);
    write_checkpoint(file, first, {0, 57});

    // Different velocities and box: the checkpoint must win; no fix setup on a resume (run_case).
    geometry::Box box;
    Atoms atoms = fixture::fcc_atoms(3.7, {3, 3, 3}, box, 63.55);
    create_velocities(atoms, 10.0, 1);
    Simulation resumed(box, std::move(atoms), fixture::cu_eam(), 0.002, 1.0);
    resumed.fixes.push_back(std::make_unique<FixNoseHooverNpt>(s));
    read_checkpoint(file, resumed);
    EXPECT_EQ(econserved(resumed), econserved(first));
    run(resumed, 63);
    ASSERT_EQ(resumed.step, straight.step);
    EXPECT_EQ(resumed.box.lo, straight.box.lo);
    EXPECT_EQ(resumed.box.hi, straight.box.hi);
    EXPECT_EQ(econserved(resumed), econserved(straight));
    for (std::size_t i = 0; i < straight.atoms.nlocal; ++i) {
      ASSERT_EQ(resumed.atoms.x[i], straight.atoms.x[i]) << (iso ? "iso" : "aniso") << " atom " << i;
      ASSERT_EQ(resumed.atoms.v[i], straight.atoms.v[i]) << (iso ? "iso" : "aniso") << " atom " << i;
    }
  }
  std::filesystem::remove(file);
}

TEST(NptDynamics, ZOnlyLeavesXAndYUnchanged) {
  Simulation sim = copper_npt(4, 3.615, 300.0, settings(1e5, false, {false, false, true}));
  const geometry::Box before = sim.box;
  run(sim, 1500);
  for (int d = 0; d < 2; ++d) {
    EXPECT_EQ(sim.box.lo[d], before.lo[d]);
    EXPECT_EQ(sim.box.hi[d], before.hi[d]);
  }
  // Uniaxial 10 GPa on copper: a few per cent of strain in z only.
  EXPECT_LT(sim.box.length().z(), 0.98 * before.length().z());
}

TEST(NptDynamics, IsoKeepsACubicBoxCubic) {
  Simulation sim = copper_npt(4, 3.615, 300.0, settings(1e5, true));
  run(sim, 500);
  const Vec3 l = sim.box.length();
  EXPECT_NEAR(l.x(), l.z(), 1e-10 * l.z());
  EXPECT_NEAR(l.y(), l.z(), 1e-10 * l.z());
}
