// The Hugoniostat against LAMMPS `fix nphug` on the same start: 512 Cu_u3 atoms (4x4x8 fcc cells
// along [100], ~320 K), `fix nphug temp 1 1 0.1 <style> 200000 200000 0.5 tchain 1 pchain 0`
// (20 GPa; e0, v0, p0 from the first step), 2000 steps of 1 fs, every 10 steps; and z with
// LAMMPS's default chains (tchain 3 pchain 3: the chains' start and the 0.01 K first target of
// the barostat chain). Uniaxial (z): the
// cell shortens along z by 8% and heats to ~430 K within 2 ps while the thermostat chases the moving
// Hugoniot target; iso: all three lengths shrink. Every term (the Hugoniot target of each step, the
// fixed masses, LAMMPS's MTK terms for one barostatted dimension, the us/up of the Rayleigh line) is
// exercised; the trajectories agree to the round-off growth LAMMPS shows between 1 and 2 MPI ranks
// (tests/fixtures/lammps_nphug/regenerate.sh).
#include "nphug_fixture.hpp"

using namespace shockfield;
using namespace shockfield::md;
using namespace shockfield::md::nphug_test;

namespace {

void check_case(const std::string& style, const std::string& name, int tchain = 1, int pchain = 0) {
  const std::vector<Row> ours = run_nphug(settings(style, 2000, tchain, pchain), 10);
  // Tolerance: 10x LAMMPS's own 1-vs-2-rank spread (our sums run in other orders than both of its
  // runs), at least 1e-12 of the quantity's largest magnitude (the columns both LAMMPS runs print
  // alike, e.g. at step 0).
  expect_follows_lammps(ours, name, 10.0, 1e-12);
  // The run did what it is for: compressed (a barostat that never moved would pass trivially).
  const auto ref = read_thermo(name + ".thermo");
  EXPECT_LT(ref.back()[kVol] / ref.front()[kVol], 0.93);
  EXPECT_GT(ref.back()[kUs], 40.0);  // Å/ps
}

}  // namespace

TEST(NphugLammps, UniaxialZFollowsLammpsFixNphugOver2000Steps) { check_case("z", "z_20GPa"); }

TEST(NphugLammps, IsoFollowsLammpsFixNphugOver2000Steps) { check_case("iso", "iso_20GPa"); }

TEST(NphugLammps, DefaultChainsFollowLammpsFixNphugOver2000Steps) { check_case("z", "z_20GPa_chains", 3, 3); }

// z in a tilted cell: the sheared, tilted 256-atom Cu start of lammps_npt_tri (tilts 4.215, -0.5,
// 0.4 Å; lammps_msst/tri_256.data), 1000 steps (fixture z_20GPa_tri). The barostat scales xz and yz
// with lz (LAMMPS's scalexz/scaleyz yes for a nonzero tilt: the uniaxial strain diag(1, 1, e)).
// Tolerance as above.
TEST(NphugLammps, UniaxialZFollowsLammpsFixNphugInATiltedCell) {
  Simulation sim = msst_test::from_data("tri_256");
  const std::vector<Row> ours = run_nphug(settings("z", 1000), 10, &sim, "tri_256");
  expect_follows_lammps(ours, "z_20GPa_tri", 10.0, 1e-12);
  const auto ref = read_thermo("z_20GPa_tri.thermo");
  EXPECT_LT(ref.back()[kVol] / ref.front()[kVol], 0.93);  // compressed
  // xz and yz followed lz (x and y kept): tilt / lz as at the start, -0.5 / 14.46 and 0.4 / 14.46.
  const double lz = sim.box.length().z();
  EXPECT_NEAR(sim.box.tilt.y() / lz, -0.5 / 14.46, 1e-12);
  EXPECT_NEAR(sim.box.tilt.z() / lz, 0.4 / 14.46, 1e-12);
  EXPECT_NEAR(sim.box.tilt.x(), 4.215, 1e-12);
}
