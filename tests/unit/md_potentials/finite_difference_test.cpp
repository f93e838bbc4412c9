// Forces are −dE/dx: central differences of the total energy, per potential, on a thermally
// perturbed lattice. Tolerance 1e-6 eV/Å (the spline table: see its case): with h = 1e-5 Å the truncation error of the C¹ splines
// (second derivative jumps at the knots) is O(h·|Δf''|) ~ 1e-7 and round-off ~ 1e-16·|E|/h ~ 1e-8.
#include <gtest/gtest.h>

#include <cmath>

#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

struct FdCase {
  std::string fixture;
  std::string toml;
  std::string folder = "lammps";  // under fixtures/
  double tolerance = 1e-6;        // eV/Å
};

class FiniteDifference : public ::testing::TestWithParam<FdCase> {};

TEST_P(FiniteDifference, ForcesAreMinusTheEnergyGradient) {
  const auto& c = GetParam();
  const System system = load_dump_system("fixtures/" + c.folder + "/" + c.fixture + ".dump");
  auto potential = potential_from_toml(c.toml, system.atoms.ntypes());
  const Evaluation base = evaluate(system, *potential, false);
  constexpr double h = 1e-5;
  double worst = 0;
  for (std::size_t i : {0ul, 7ul, 42ul, 101ul, system.atoms.nlocal - 1}) {
    for (int d = 0; d < 3; ++d) {
      System plus = system, minus = system;
      plus.atoms.x[i][d] += h;
      minus.atoms.x[i][d] -= h;
      const double ep = evaluate(plus, *potential, false).result.energy;
      const double em = evaluate(minus, *potential, false).result.energy;
      const double fd = -(ep - em) / (2 * h);
      worst = std::max(worst, std::abs(fd - base.force[i][d]));
      EXPECT_NEAR(fd, base.force[i][d], c.tolerance) << c.fixture << " atom " << i << " dim " << d;
    }
  }
  std::printf("%-16s max |F_fd - F| = %.1e eV/A\n", c.fixture.c_str(), worst);
}

INSTANTIATE_TEST_SUITE_P(
    Potentials, FiniteDifference,
    ::testing::Values(
        FdCase{"cu_u3_thermal", "[potential]\nstyle = \"eam\"\nfile = \"Cu_u3.eam\"\n"},
        FdCase{"al_zhou_thermal",
               "[potential]\nstyle = \"eam/alloy\"\nfile = \"Al_zhou.eam.alloy\"\nelements = [\"Al\"]\n"},
        FdCase{"fe_mm_thermal",
               "[potential]\nstyle = \"eam/fs\"\nfile = \"Fe_mm.eam.fs\"\nelements = [\"Fe\"]\n"},
        FdCase{"cuni_thermal", "[potential]\nstyle = \"eam/alloy\"\nfile = \"CuNi.eam.alloy\"\n"
                               "elements = [\"Cu\", \"Ni\"]\n"},
        FdCase{"alfe_mm_thermal", "[potential]\nstyle = \"eam/fs\"\nfile = \"AlFe_mm.eam.fs\"\n"
                                  "elements = [\"Fe\", \"Al\"]\n"},
        FdCase{"lj_thermal", "[potential]\nstyle = \"lj/cut\"\ncutoff = 8.5\nshift = true\n"
                             "epsilon = 0.0104\nsigma = 3.4\n[[potential.pair]]\ntypes = [2, 2]\n"
                             "epsilon = 0.008\nsigma = 3.0\ncutoff = 7.0\n"},
        // A spline table: E and F/r are splined separately (in r from the file, then in r²), so
        // F = −dE/dr only to the splines' error (theory/md-table.md): measured 3.6e-6 eV/Å on
        // forces of ~2 eV/Å at N = 1000; tolerance 1e-5.
        FdCase{"spline_1000", "[potential]\nstyle = \"table\"\ninterpolation = \"spline\"\npoints = 1000\n"
                              "file = \"fixtures/lammps_table/pair.table\"\n[[potential.pair]]\ntypes = [1, 1]\n"
                              "keyword = \"M11\"\n[[potential.pair]]\ntypes = [2, 2]\nkeyword = \"M22\"\n"
                              "[[potential.pair]]\ntypes = [1, 2]\nkeyword = \"M12\"\n", "lammps_table", 1e-5},
        // ADP on a distorted cell: the Al-Cu alloy in a sheared prism with a void (the dipole and
        // quadrupole forces are not along the pairs; same C¹ splines, same tolerance as EAM).
        FdCase{"alcu_sheared_void", "[potential]\nstyle = \"adp\"\nfile = \"AlCu.adp\"\n"
                                    "elements = [\"Al\", \"Cu\"]\n", "lammps_adp"}),
    [](const auto& info) { return info.param.fixture; });

}  // namespace
}  // namespace shockfield::md::potentials::testing
