// Slow: MSST against LAMMPS `fix msst` on 4096 Cu_u3 atoms (8x8x16 fcc cells along [100], ~300 K),
// `fix msst z 60 q 1000 mu 1000 tscale 0.01` (as the 512-atom default-suite test: the cell's
// strain obeys the same equation for any cell size), 2000 steps of 1 fs, rows every 50 steps
// (tests/fixtures/lammps_msst/regenerate.sh). About 40 s on one core.
#include "unit/md_msst/msst_fixture.hpp"

using namespace shockfield::md::msst_test;

TEST(MsstLammpsSlow, FollowsLammpsFixMsstOn4096AtomsOver2000Steps) {
  const std::vector<Row> ours = run_msst("cu_4096", settings(1000.0, 1000.0, 2000), 50);
  // As the default-suite test: 10x LAMMPS's own 1-vs-2-rank spread, at least 1e-12 relative.
  expect_follows_lammps(ours, "cu_4096", 10.0, 1e-12);
}
