// The Us–Up sweep of examples/md_shock_piston/case.toml (Cu_u3 EAM, [100], 8×8×50 cells, 300 K)
// at piston speeds 0.5, 1.0, 1.5 and 2.0 km/s against the LAMMPS peer sweep of the same setup
// (tests/fixtures/lammps_shock: in.shock with fix wall/piston, profiles from fix ave/chunk,
// extract_us_up.py with the same front definition; regenerate.sh). The two codes draw different
// thermal states, so their Us differ by statistics only: each Us carries the standard error of
// its front-position fit (residual scatter of the front about its line, ~25 frames); Us must
// agree within 3 combined standard errors, plus 0.02 km/s for the correlation of successive
// front positions that the residual error does not see (the front moves about one bin between
// frames). Label "slow" (about 4 x 3500 steps of 12,800 atoms): ctest --preset release -L slow.
// SHOCKFIELD_SWEEP_DIR=<folder> reuses a finished sweep there instead of running a fresh one.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "shockfield/md/hugoniot_sweep.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

// lammps_sweep.csv: header, then piston_speed_km_s, up_km_s, us_km_s, us_stderr_km_s, ...
std::vector<std::vector<double>> read_rows(const std::string& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::vector<double> row;
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(MdHugoniotSweep, CopperUsMatchesLammpsWithinScatter) {
  const auto lammps = read_rows("fixtures/lammps_shock/lammps_sweep.csv");
  ASSERT_EQ(lammps.size(), 4u) << "run tests/fixtures/lammps_shock/regenerate.sh";
  HugoniotSweepSettings s;
  s.case_file = "../examples/md_shock_piston/case.toml";
  s.speeds = {0.5, 1.0, 1.5, 2.0};
  const char* reuse = std::getenv("SHOCKFIELD_SWEEP_DIR");
  s.folder = reuse ? std::filesystem::path(reuse) : shockfield::testing::scratch_path("shockfield_slow_sweep");
  s.overwrite = reuse == nullptr;
  s.quiet = true;
  const HugoniotSweep sweep = run_hugoniot_sweep(s);
  ASSERT_EQ(sweep.points.size(), 4u);
  std::printf("piston   Up ours  Up LAMMPS   Us ours          Us LAMMPS        |dUs|/sigma\n");
  for (std::size_t k = 0; k < 4; ++k) {
    const SweepPoint& p = sweep.points[k];
    const std::vector<double>& l = lammps[k];
    ASSERT_NEAR(p.piston, l[0], 1e-9);
    const double sigma = std::hypot(p.us_stderr, l[3]);
    std::printf("%5.2f   %7.4f  %7.4f     %.4f+-%.4f  %.4f+-%.4f  %.2f\n", p.piston, p.up, l[1], p.us, p.us_stderr,
                l[2], l[3], std::abs(p.us - l[2]) / sigma);
    EXPECT_LT(std::abs(p.us - l[2]), 3.0 * sigma + 0.02) << "piston " << p.piston << " km/s";
    EXPECT_LT(std::abs(p.up - l[1]), 0.02) << "piston " << p.piston << " km/s";  // both ≈ the piston speed
  }
  ASSERT_TRUE(sweep.fit.has_value());
  std::printf("ours: Us = %.3f(%.3f) + %.3f(%.3f) Up; experiment (Marsh 1980): %.3f + %.3f Up\n", sweep.fit->c0(),
              sweep.fit->line.intercept_stderr, sweep.fit->s(), sweep.fit->line.slope_stderr, kCopperC0, kCopperS);
}
