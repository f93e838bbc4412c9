// Data and dump files that a mutation fuzzer (tests/fuzz) found crashing, hanging or silently
// truncated (issue 14): each is now an InputError naming the file and line, checked before
// anything is sized by a count, in time independent of the values.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/scratch_path.hpp"

#include "shockfield/core/error.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::io {
namespace {

const std::string kHead = "title\n\n2 atoms\n1 atom types\n\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\nMasses\n\n1 1.0\n\nAtoms\n\n";

// A folder of this test process (ctest runs tests side by side).
std::string scratch(const std::string& name) {
  const auto dir = shockfield::testing::scratch_path("shockfield_io_hardening");
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string data_error(const std::string& text) {
  const std::string path = scratch("hard.data");
  std::ofstream(path) << text;
  try {
    read_data(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DataHardening, ImageFlagsOutsideIntAreRefused) {
  const std::string e = data_error(kHead + "1 1 1 1 1 2147483648 0 0\n2 1 2 2 2 0 0 0\n");
  EXPECT_NE(e.find("hard.data:16: image flag ix = 2147483648 is outside the range"), std::string::npos) << e;
}

TEST(DataHardening, FarCoordinatesInAPeriodicBoxWrapOrAreRefusedAtOnce) {
  // 1e300 is 1e299 box lengths away: refused (it used to loop forever); 1e9 wraps by floor.
  const auto start = std::chrono::steady_clock::now();
  for (const char* far : {"1e300", "9.2e18", "-1e20"}) {
    const std::string e = data_error(kHead + "1 1 " + far + " 1 1\n2 1 2 2 2\n");
    EXPECT_NE(e.find("hard.data:16: atom 1"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot be wrapped"), std::string::npos) << e;
  }
  const std::string path = scratch("far.data");
  std::ofstream(path) << kHead + "1 1 1000000003.5 1 1 0 0 0\n2 1 2 2 2\n";
  const DataFile d = read_data(path);
  EXPECT_DOUBLE_EQ(d.atoms.x[0].x(), 3.5);
  EXPECT_EQ(d.atoms.image[0][0], 100000000);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(DataHardening, CountsLargerThanTheFileAreRefusedBeforeAllocating) {
  std::string e = data_error("t\n\n4000000000000 atoms\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n"
                             "0 1 zlo zhi\nAtoms\n\n1 1 0 0 0\n");
  EXPECT_NE(e.find("hard.data:8: the header declares 4000000000000 atoms, which cannot fit in a file of"),
            std::string::npos) << e;
  e = data_error("t\n\n2 atoms\n9223372036854775807 atom types\n");
  EXPECT_NE(e.find("hard.data:4: expected a number of atom types in 1..100000"), std::string::npos) << e;
}

TEST(DataHardening, BoxWhoseLengthOverflowsIsRefused) {
  const std::string e = data_error("t\n\n2 atoms\n1 atom types\n-1e308 1e308 xlo xhi\n");
  EXPECT_NE(e.find("hard.data:5: expected xlo < xhi with a finite length"), std::string::npos) << e;
}

std::string dump_error(const std::string& text) {
  std::istringstream in(text);
  try {
    for (const auto& f : read_dump(in, "hard.dump")) f.ids(), f.types();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kDumpHead = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n";
const std::string kDumpBox = "ITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id type x y z\n";

TEST(DumpHardening, HugeAtomCountEndsAtTheEndOfTheFileNotInBadAlloc) {
  const std::string e = dump_error(kDumpHead + "9223372036854775807\n" + kDumpBox + "1 1 0 0 0\n");
  EXPECT_NE(e.find("hard.dump:11: unexpected end of file, expected atom row 2 of 9223372036854775807"),
            std::string::npos) << e;
}

TEST(DumpHardening, IdsAndTypesMustBeWholeNumbersInRange) {
  std::string e = dump_error(kDumpHead + "1\n" + kDumpBox + "1e300 1 0 0 0\n");
  EXPECT_NE(e.find("row 1 has id = 1e+300"), std::string::npos) << e;
  e = dump_error(kDumpHead + "1\n" + kDumpBox + "1 4294967296 0 0 0\n");
  EXPECT_NE(e.find("row 1 has type = 4294967296"), std::string::npos) << e;
  e = dump_error(kDumpHead + "1\n" + kDumpBox + "1 1.5 0 0 0\n");
  EXPECT_NE(e.find("expected a whole number"), std::string::npos) << e;
}

}  // namespace
}  // namespace shockfield::io
