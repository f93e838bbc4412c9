// Bad potential input: truncated and malformed files, Fortran D exponents, element and type
// mismatches, missing files, bad [potential] keys. Each must be an InputError whose message
// names the file (and line or key) and what was expected.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>
#include <sstream>


#include "shockfield/core/error.hpp"
#include "shockfield/md/potentials/eam_file.hpp"
#include "shockfield/md/potentials/eam_tables.hpp"
#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

const std::filesystem::path kPotentials = "/usr/share/lammps/potentials";

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = shockfield::testing::scratch_path("shockfield_potentials");
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes the first `lines` lines of `source` (all when negative) with `replace` applied.
  std::filesystem::path write(const std::string& name, const std::filesystem::path& source,
                              int lines, const std::string& from = "", const std::string& to = "") {
    std::ifstream in(source);
    std::ofstream out(dir_ / name);
    std::string line;
    for (int k = 0; (lines < 0 || k < lines) && std::getline(in, line); ++k) {
      if (!from.empty())
        if (const auto at = line.find(from); at != std::string::npos) line.replace(at, from.size(), to);
      out << line << '\n';
    }
    return dir_ / name;
  }

  std::filesystem::path dir_;
};

TEST_F(BadInput, TruncatedFuncflNamesFileLineAndTable) {
  const auto file = write("cut.eam", kPotentials / "Cu_u3.eam", 150);
  expect_input_error([&] { read_funcfl(file); },
                     {"cut.eam:150:", "unexpected end of file", "of the 500 values of Z(r)"});
}

TEST_F(BadInput, TruncatedSetflHeader) {
  const auto file = write("cut.eam.alloy", kPotentials / "CuNi.eam.alloy", 4);
  expect_input_error([&] { read_setfl(file, false); },
                     {"cut.eam.alloy:4:", "expected the grid line"});
}

TEST_F(BadInput, TruncatedFinnisSinclairPairTable) {
  // Fe_mm.eam.fs: 5 header lines, 1 element line, then 2000 lines each for F, rho, r*phi.
  const auto file = write("cut.eam.fs", kPotentials / "Fe_mm.eam.fs", 5000);
  expect_input_error([&] { read_setfl(file, true); }, {"cut.eam.fs:5000:", "r*phi(r) of Fe-Fe"});
}

TEST_F(BadInput, ElementLineMustMatchItsCount) {
  const auto file = write("count.eam.alloy", kPotentials / "CuNi.eam.alloy", -1, "2  Ni  Cu", "3  Ni  Cu");
  expect_input_error([&] { read_setfl(file, false); },
                     {"count.eam.alloy:4:", "N = 3 and 2 names"});
}

TEST_F(BadInput, NonNumericValue) {
  const auto file = write("word.eam", kPotentials / "Cu_u3.eam", -1,
                          "-3.1561636903424350e-01", "-3.15616369O3424350e-01");
  expect_input_error([&] { read_funcfl(file); }, {"word.eam:4:", "expected a number in F(rho)"});
}

TEST_F(BadInput, GridMustBeUsable) {
  const auto file = write("grid.eam", kPotentials / "Cu_u3.eam", -1, "  500  5.01", "  3  5.01");
  expect_input_error([&] { read_funcfl(file); }, {"grid.eam:3:", "Nrho and Nr >= 5"});
}

// ADP files (Ni.adp: 5 header lines, the element line, 3001 lines of F, then 10000 lines each of
// rho, r*phi, u and w).
TEST_F(BadInput, AdpFileWithoutItsAngularTablesNamesTheMissingTable) {
  // Cut after r*phi: the setfl part of the file is whole, u(r) and w(r) are missing.
  const auto file = write("no_uw.adp", kPotentials / "Ni.adp", 23007);
  expect_input_error([&] { read_adp(file); },
                     {"no_uw.adp:23007:", "unexpected end of file after 0 of the 10000 values",
                      "ADP dipole function u(r) of Ni-Ni"});
}

TEST_F(BadInput, TruncatedAdpQuadrupoleTable) {
  const auto file = write("cut.adp", kPotentials / "Ni.adp", 40000);
  expect_input_error([&] { read_adp(file); },
                     {"cut.adp:40000:", "after 6993 of the 10000 values", "quadrupole function w(r) of Ni-Ni"});
}

TEST_F(BadInput, AdpElementCountMustMatchItsNames) {
  const auto file = write("count.adp", kPotentials / "Ni.adp", -1, "1 Ni", "2 Ni");
  expect_input_error([&] { read_adp(file); }, {"count.adp:4:", "N = 2 and 1 names"});
  expect_input_error(
      [] { potential_from_toml("[potential]\nstyle = \"adp\"\nfile = \"AlCu.adp\"\nelements = [\"Al\"]\n", 2); },
      {"test.toml:4", "potential.elements", "one element per atom type (2 names, one of: Al Cu)", "found 1"});
  expect_input_error(
      [] { potential_from_toml("[potential]\nstyle = \"adp\"\nfile = \"Ni.adp\"\nelements = [\"Cu\"]\n", 1); },
      {"test.toml:4", "'Cu' is not in", "Ni.adp (it has: Ni)"});
}

TEST_F(BadInput, FortranDExponentsAreReadAsE) {
  // The same funcfl file with every exponent written as D (upper and lower case) reads the same.
  std::ifstream in(kPotentials / "Cu_u3.eam");
  std::ofstream out(dir_ / "fortran.eam");
  std::string line;
  for (int k = 0; std::getline(in, line); ++k) {
    if (k >= 2)
      for (auto& ch : line)
        if (ch == 'e') ch = (k % 2) ? 'D' : 'd';
    out << line << '\n';
  }
  out.close();
  const auto a = read_funcfl(kPotentials / "Cu_u3.eam");
  const auto b = read_funcfl(dir_ / "fortran.eam");
  EXPECT_EQ(a.grid.drho, b.grid.drho);
  EXPECT_EQ(a.frho, b.frho);
  EXPECT_EQ(a.zr, b.zr);
  EXPECT_EQ(a.rhor, b.rhor);
}

TEST_F(BadInput, MissingFileListsWhereItLooked) {
  expect_input_error(
      [] { potential_from_toml("[potential]\nstyle = \"eam\"\nfile = \"nope.eam\"\n", 1); },
      {"test.toml:3", "potential.file", "'nope.eam' not found", "/usr/share/lammps/potentials/nope.eam",
       std::filesystem::current_path().string()});
}

TEST_F(BadInput, ElementNotInFile) {
  expect_input_error(
      [] {
        potential_from_toml("[potential]\nstyle = \"eam/alloy\"\nfile = \"CuNi.eam.alloy\"\n"
                            "elements = [\"Cu\", \"Fe\"]\n", 2);
      },
      {"test.toml:4", "potential.elements", "'Fe' is not in", "CuNi.eam.alloy", "Ni Cu"});
}

TEST_F(BadInput, ElementCountMustMatchTypes) {
  expect_input_error(
      [] {
        potential_from_toml("[potential]\nstyle = \"eam/fs\"\nfile = \"Fe_mm.eam.fs\"\n"
                            "elements = [\"Fe\"]\n", 2);
      },
      {"test.toml:4", "one element per atom type (2 names", "found 1"});
}

TEST_F(BadInput, AtomsWithOtherTypesOrNamesAreRejected) {
  auto potential = potential_from_toml(
      "[potential]\nstyle = \"eam/alloy\"\nfile = \"CuNi.eam.alloy\"\nelements = [\"Cu\", \"Ni\"]\n", 2);
  Atoms atoms;
  atoms.mass = {63.5};
  expect_input_error([&] { potential->check_types(atoms); }, {"maps 2 atom types, the atoms have 1"});
  atoms.mass = {63.5, 58.7};
  atoms.type_names = {"Ni", "Cu"};
  expect_input_error([&] { potential->check_types(atoms); }, {"type 1 is Ni", "maps it to Cu"});
}

TEST_F(BadInput, UnknownStyleAndUnmixableLj) {
  expect_input_error([] { potential_from_toml("[potential]\nstyle = \"tersoff\"\n", 1); },
                     {"test.toml:2", "potential.style"});
  expect_input_error(
      [] {
        potential_from_toml("[potential]\nstyle = \"lj/cut\"\ncutoff = 5.0\n[[potential.pair]]\n"
                            "types = [1, 1]\nepsilon = 0.01\nsigma = 3.0\n", 2);
      },
      {"potential.pair", "type pair 1 2", "none for type 2"});
}

// Values a mutation fuzzer found crashing or hanging a run after the file was accepted
// (issue 14): non-finite values, masses, grid steps and cutoffs out of range, and counts larger
// than the file. Each is now refused where it is read, naming the file and line.
TEST_F(BadInput, NonFiniteTableValuesAreRefused) {
  for (const char* bad : {"nan", "inf", "-inf", "Infinity"}) {
    const auto file = write("nonfinite.eam", kPotentials / "Cu_u3.eam", -1, "-3.1561636903424350e-01", bad);
    expect_input_error([&] { read_funcfl(file); }, {"nonfinite.eam:4:", "finite number in F(rho)", bad});
  }
}

TEST_F(BadInput, MassOutOfRangeIsRefused) {
  for (const char* bad : {"inf", "1e-300", "0", "-63.55"}) {
    const auto file = write("mass.eam", kPotentials / "Cu_u3.eam", -1, "63.550", bad);
    expect_input_error([&] { read_funcfl(file); }, {"mass.eam:2:", "mass"});
  }
}

TEST_F(BadInput, GridStepsAndCutoffMustFitTheTable) {
  // dr = 1e-300: the tables end at 5e-298 Å, far inside the cutoff (a radial index of 1e300
  // overflowed the int cast of the force kernel).
  auto file = write("dr.eam", kPotentials / "Cu_u3.eam", -1, "1.0000000000000009e-02", "1e-300");
  expect_input_error([&] { read_funcfl(file); }, {"dr.eam:3:", "beyond the tabulated range"});
  file = write("cut.eam", kPotentials / "Cu_u3.eam", -1, "4.9499999999999886e+00", "1e300");
  expect_input_error([&] { read_funcfl(file); }, {"cut.eam:3:", "cutoff 1e+300"});
  file = write("dr308.eam", kPotentials / "Cu_u3.eam", -1, "1.0000000000000009e-02", "1e308");
  expect_input_error([&] { read_funcfl(file); }, {"dr308.eam:3:", "are not finite"});  // Nr dr = inf
  file = write("drho.eam", kPotentials / "Cu_u3.eam", -1, "5.0100200400801306e-04", "-inf");
  expect_input_error([&] { read_funcfl(file); }, {"drho.eam:3:", "finite number in drho"});
}

TEST_F(BadInput, TableLongerThanTheFileIsRefusedBeforeAllocating) {
  const auto file = write("count.eam", kPotentials / "Cu_u3.eam", -1, "  500  5.01", "  2000000000  5.01");
  expect_input_error([&] { read_funcfl(file); }, {"count.eam:3:", "cannot fit in a file of"});
}

TEST_F(BadInput, UnresolvableTableSpacingIsRefused) {
  // drho = 1e-300 was accepted (issue 14): every density of the crystal then lay beyond the
  // table's last row. Spacings below 1e-10 are refused by line; 1e-10 itself is accepted.
  auto file = write("drho.eam", kPotentials / "Cu_u3.eam", -1, "5.0100200400801306e-04", "1e-300");
  expect_input_error([&] { read_funcfl(file); }, {"drho.eam:3:", "drho = 1e-300", "must be >= 1e-10"});
  file = write("drho_min.eam", kPotentials / "Cu_u3.eam", -1, "5.0100200400801306e-04", "1e-10");
  EXPECT_EQ(read_funcfl(file).grid.drho, 1e-10);
}

TEST(Spline, ReproducesACubicInsideTheTable) {
  // interpolate() is exact for polynomials its 5-point slopes differentiate exactly (cubics) on
  // the inner intervals; check value and derivative at the middle of one interval.
  std::vector<double> f;
  const double delta = 0.1;
  auto g = [](double x) { return 1.0 - 2.0 * x + 0.5 * x * x + 0.25 * x * x * x; };
  for (int k = 0; k < 20; ++k) f.push_back(g(k * delta));
  const auto s = spline_coefficients(f, delta);
  const double x = 7.5 * delta, p = 0.5;
  const auto& c = s[7];
  EXPECT_NEAR(((c[3] * p + c[4]) * p + c[5]) * p + c[6], g(x), 1e-13);
  EXPECT_NEAR((c[0] * p + c[1]) * p + c[2], -2.0 + x + 0.75 * x * x, 1e-12);
}

}  // namespace
}  // namespace shockfield::md::potentials::testing
