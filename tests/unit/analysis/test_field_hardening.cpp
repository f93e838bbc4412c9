// Field files a mutation fuzzer (tests/fuzz) found accepted with infinite values, or sized from
// extents and offsets beyond the file (issue 14): each is an InputError naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/scratch_path.hpp"

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/core/error.hpp"

namespace sa = shockfield::analysis;

namespace {

std::string field_error(const std::string& name, const std::string& text) {
  const auto dir = shockfield::testing::scratch_path("shockfield_field_hardening");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  try {
    sa::read_grid_field(path);
  } catch (const shockfield::InputError& e) {
    return e.what();
  }
  return "";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

TEST(FieldHardening, InfiniteValuesAndGeometryAreRefused) {
  std::string e = field_error("inf.csv", "1,2\ninf,3\n");
  EXPECT_NE(e.find("inf.csv:2: 'inf' is infinite"), std::string::npos) << e;
  e = field_error("origin.csv", "# origin = 0 nan 0\n1,2\n");
  EXPECT_NE(e.find("origin.csv:1: 'nan' is not a finite number"), std::string::npos) << e;
  const std::string vtk = slurp("fixtures/analysis/fields/points.vtk");
  e = field_error("spacing.vtk", replaced(vtk, "SPACING 0.5", "SPACING inf"));
  EXPECT_NE(e.find("spacing.vtk:"), std::string::npos) << e;
}

TEST(FieldHardening, GridsLargerThanTheFileAreRefusedBeforeAllocating) {
  const std::string vtk = slurp("fixtures/analysis/fields/points.vtk");
  std::string e = field_error("dims.vtk", replaced(vtk, "DIMENSIONS 4 3 2", "DIMENSIONS 1000000000000000 1000000000000000 1000"));
  EXPECT_NE(e.find("cannot fit in a file of"), std::string::npos) << e;
  const std::string vti = slurp("fixtures/analysis/fields/raw.vti");
  e = field_error("extent.vti", replaced(vti, "WholeExtent=\"0 3", "WholeExtent=\"0 1e300"));
  EXPECT_NE(e.find("extent.vti:"), std::string::npos) << e;
  EXPECT_NE(e.find("WholeExtent"), std::string::npos) << e;
  e = field_error("offset.vti", replaced(vti, "offset=\"0\"", "offset=\"1e300\""));
  EXPECT_NE(e.find("offset 1e+300"), std::string::npos) << e;
}

}  // namespace
