// Bad pair_style table input: each defect of a table file is an InputError naming the file, the
// line and what was expected; each bad [potential] key names the case file and key; a pair
// closer than its table's inner distance stops the run with a RunError naming the atoms.
#include <gtest/gtest.h>

#include <fstream>

#include "shockfield/md/potentials/pair_table_file.hpp"
#include "support/scratch_path.hpp"
#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

// A valid two-section file: A (r column, 4 lines) and B (R spacing, 3 lines).
const std::string kGood =
    "# test table\n"
    "\n"
    "A\n"
    "N 4\n"
    "\n"
    "1 2.0 1.0 3.0\n"
    "2 3.0 0.2 0.5\n"
    "3 4.0 0.05 0.1\n"
    "4 5.0 0.0 0.0\n"
    "\n"
    "B   # comment after the keyword\n"
    "N 3 R 2.0 4.0\n"
    "\n"
    "1 2.0 1.0 1.0\n"
    "2 3.0 0.5 0.5\n"
    "3 4.0 0.0 0.0\n";

class PairTableBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = shockfield::testing::scratch_path("shockfield_pair_table");
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // kGood with `from` replaced by `to`, written to dir_/t.table.
  std::filesystem::path write(const std::string& from = "", const std::string& to = "") {
    std::string text = kGood;
    if (!from.empty()) text.replace(text.find(from), from.size(), to);
    std::ofstream(dir_ / "t.table") << text;
    return dir_ / "t.table";
  }

  // A [potential] table for one atom type using section `keyword` of `file`, plus `extra` lines.
  static std::string toml(const std::filesystem::path& file, const std::string& keyword,
                          const std::string& extra = "", const std::string& interpolation = "linear",
                          int points = 100) {
    return "[potential]\nstyle = \"table\"\ninterpolation = \"" + interpolation + "\"\npoints = " +
           std::to_string(points) + "\nfile = \"" + file.string() + "\"\nkeyword = \"" + keyword +
           "\"\n" + extra;
  }

  std::filesystem::path dir_;
};

TEST_F(PairTableBadInput, GoodFileReads) {
  const auto a = read_pair_table(write(), "A");
  EXPECT_EQ(a.r.size(), 4u);
  const auto b = read_pair_table(write(), "B");
  EXPECT_EQ(b.spacing, PairTableSection::Spacing::r);
  EXPECT_DOUBLE_EQ(b.r[1], 3.0);
}

TEST_F(PairTableBadInput, MissingKeywordListsTheSections) {
  const auto file = write();
  expect_input_error([&] { read_pair_table(file, "C"); }, {"t.table", "no table section 'C'", "A, B"});
  expect_input_error([&] { potential_from_toml(toml(file, "C"), 1); },
                     {"test.toml", "potential.keyword", "no table section 'C'"});
}

TEST_F(PairTableBadInput, ParameterLineWithoutN) {
  expect_input_error([&] { read_pair_table(write("N 3 R", "R"), "B"); },
                     {"t.table:12:", "expected the parameter line 'N n"});
}

TEST_F(PairTableBadInput, NTooSmall) {
  expect_input_error([&] { read_pair_table(write("N 3 R", "N 1 R"), "B"); },
                     {"t.table:12:", "expected N >= 2", "N = 1"});
  // N larger than the file can hold is refused before anything is sized by it.
  expect_input_error([&] { read_pair_table(write("N 3 R", "N 2000000000 R"), "B"); },
                     {"t.table:12:", "cannot fit"});
  // The inner table needs two points, as LAMMPS's pair_style table N.
  expect_input_error([&] { potential_from_toml(toml(write(), "A", "", "linear", 1), 1); },
                     {"potential.points", "expected"});
}

TEST_F(PairTableBadInput, NonMonotonicDistances) {
  expect_input_error([&] { read_pair_table(write("3 4.0 0.05", "3 2.5 0.05"), "A"); },
                     {"t.table:8:", "expected distances increasing", "r = 2.5 after 3"});
  expect_input_error([&] { read_pair_table(write("1 2.0 1.0 3.0", "1 0 1.0 3.0"), "A"); },
                     {"t.table:6:", "expected a distance r > 0"});
  expect_input_error([&] { read_pair_table(write("R 2.0 4.0", "R 4.0 2.0"), "B"); },
                     {"t.table:12:", "expected 0 < rlo < rhi"});
}

TEST_F(PairTableBadInput, CutoffBeyondTheTable) {
  const auto file = write();
  expect_input_error([&] { potential_from_toml(toml(file, "A", "cutoff = 5.5\n"), 1); },
                     {"test.toml", "potential.cutoff", "cutoff 5.5 Å is outside the table", "section A",
                      "rhi = 5 Å"});
  expect_input_error([&] { potential_from_toml(toml(file, "B", "cutoff = 2.0\n"), 1); },
                     {"potential.cutoff", "rlo = 2 Å"});
}

TEST_F(PairTableBadInput, MalformedLines) {
  expect_input_error([&] { read_pair_table(write("2 3.0 0.2 0.5", "2 3.0 0.2"), "A"); },
                     {"t.table:7:", "expected 'index r energy force', found 3 words"});
  expect_input_error([&] { read_pair_table(write("2 3.0 0.2 0.5", "2 3.0 nan 0.5"), "A"); },
                     {"t.table:7:", "the energy (a finite number)"});
  expect_input_error([&] { read_pair_table(write("N 4\n\n", "N 4\n"), "A"); },
                     {"t.table:5:", "expected a blank line after the parameter line of section A"});
  expect_input_error([&] { read_pair_table(write("N 4\n", "N 4 Q 1\n"), "A"); },
                     {"t.table:4:", "expected a table parameter N, R, RSQ or FPRIME, found 'Q'"});
  expect_input_error([&] { read_pair_table(write("N 4\n", "N 4 FPRIME 1\n"), "A"); },
                     {"t.table:4:", "expected dF/dr at the last point after 'FPRIME'"});
  expect_input_error([&] { read_pair_table(write("3 4.0 0.0 0.0\n", ""), "B"); },
                     {"t.table", "unexpected end of file after 2 of the 3 lines of section B"});
}

TEST_F(PairTableBadInput, ValuesThatOverflowTheSplines) {
  // Finite in the file, infinite once splined (found by the fuzzer: a SIGSEGV before).
  expect_input_error([&] { potential_from_toml(toml(write("2 3.0 0.2 0.5", "2 3.0 0.2 1e308"), "A"), 1); },
                     {"potential.keyword", "t.table section A", "non-finite energy or force"});
}

TEST_F(PairTableBadInput, BitmapIsRefused) {
  expect_input_error([&] { read_pair_table(write("N 3 R 2.0 4.0", "N 4 BITMAP 2.0 4.0"), "B"); },
                     {"t.table:12:", "BITMAP tables", "not supported"});
}

TEST_F(PairTableBadInput, EveryTypePairNeedsATable) {
  const auto file = write();
  const std::string pairs = "[potential]\nstyle = \"table\"\ninterpolation = \"spline\"\npoints = 100\nfile = \"" +
                            file.string() + "\"\n[[potential.pair]]\ntypes = [1, 1]\nkeyword = \"A\"\n"
                            "[[potential.pair]]\ntypes = [2, 2]\nkeyword = \"B\"\n";
  expect_input_error([&] { potential_from_toml(pairs, 2); },
                     {"potential.pair", "a table for type pair 1 2", "does not mix"});
  expect_input_error([&] { potential_from_toml(pairs + "[[potential.pair]]\ntypes = [1, 2]\n", 2); },
                     {"potential.pair[2].keyword", "missing"});
  expect_input_error([&] { potential_from_toml(toml(file, "A", "", "cubic"), 1); },
                     {"potential.interpolation", "expected one of"});
}

TEST_F(PairTableBadInput, PairInsideTheInnerDistanceStopsTheRun) {
  // Two atoms 1.5 Å apart, the table starting at 2 Å (LAMMPS: "Pair distance < table inner cutoff").
  System system;
  system.box.lo = Vec3::Zero();
  system.box.hi = Vec3::Constant(20.0);
  system.atoms.add(Vec3(5.0, 5.0, 5.0), 0, 1);
  system.atoms.add(Vec3(6.5, 5.0, 5.0), 0, 2);
  system.atoms.mass = {1.0};
  auto potential = potential_from_toml(toml(write(), "A"), 1);
  expect_input_error<RunError>([&] { evaluate(system, *potential); },
                               {"atoms 1 and 2", "1.5 Å apart", "section A", "covers 2 to 5 Å"});
}

}  // namespace
}  // namespace shockfield::md::potentials::testing
