// `shockfield analyze` reads a parallel image (.pvti over .vti pieces, io/vtk_pieces) as the same
// grid written as one .vti: point data with void (NaN) points on a 3D grid, cell data on a 2D
// one, every value and void flag equal. Summaries that do not describe their pieces are input
// errors naming the file: a missing piece, a piece outside the WholeExtent or of another size, a
// Source outside the folder or not a .vti (a .pvti naming itself would recurse).
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/io/vtk_pieces.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

fs::path fresh_dir(const char* name) {
  const fs::path dir = shockfield::testing::scratch_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The grid written once as a .vti and once as a .pvti of `pieces` pieces: both read back alike.
void expect_same_field(const fs::path& dir, const io::VtkImage& image, int pieces, const std::string& array) {
  io::VtkFormat format{io::VtkEncoding::Zlib, io::VtkPrecision::Float64};
  const std::string single = io::write_image_frame(dir, "single", image, format);
  format.pieces = pieces;
  const std::string parallel = io::write_image_frame(dir, "parallel", image, format);
  ASSERT_EQ(parallel, "parallel.pvti");
  const analysis::GridField a = analysis::read_grid_field((dir / single).string(), array);
  const analysis::GridField b = analysis::read_grid_field((dir / parallel).string(), array);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.spacing, b.spacing);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.is_void, b.is_void);
}

TEST(PvtiReader, PointDataWithVoidsReadsAsTheSingleFile) {
  io::VtkImage image;
  image.points = {5, 4, 6};
  image.origin = {1, 2, 3};
  image.spacing = {0.5, 0.25, 2};
  std::vector<double> v(5 * 4 * 6);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = i % 7 == 3 ? std::numeric_limits<double>::quiet_NaN() : 0.1 * i;
  image.point_data = {{"velocity", 3, std::vector<double>(3 * v.size(), 1.0), "m/s"}, {"pressure", 1, v, "Pa"}};
  expect_same_field(fresh_dir("shockfield_pvti_points"), image, 3, "pressure");
  const analysis::GridField f =
      analysis::read_grid_field((shockfield::testing::scratch_path("shockfield_pvti_points") / "parallel.pvti").string());
  EXPECT_EQ(f.void_count(), (v.size() + 3) / 7) << "the first scalar array, as in a .vti";
}

TEST(PvtiReader, CellDataReadsAsTheSingleFile) {
  io::VtkImage image;
  image.points = {8, 3, 1};  // DBM: 7 × 2 cells on the corner extent
  std::vector<double> rho(7 * 2);
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = 1.0 + i;
  image.cell_data = {{"rho", 1, rho, "1"}};
  expect_same_field(fresh_dir("shockfield_pvti_cells"), image, 3, "rho");
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The error of reading the summary with `from` replaced by `to`.
std::string error_of(const fs::path& dir, const std::string& from, const std::string& to) {
  std::string text = read_text(dir / "parallel.pvti");
  const auto at = text.find(from);
  if (at == std::string::npos) return "the fixture lacks " + from;
  text.replace(at, from.size(), to);
  std::ofstream(dir / "broken.pvti") << text;
  try {
    analysis::read_grid_field((dir / "broken.pvti").string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PvtiReader, SummariesThatDoNotDescribeTheirPiecesAreInputErrors) {
  const fs::path dir = fresh_dir("shockfield_pvti_errors");
  io::VtkImage image;
  image.points = {7, 3, 1};
  image.point_data = {{"p", 1, std::vector<double>(21, 2.0), "Pa"}};
  io::VtkFormat format{io::VtkEncoding::Raw, io::VtkPrecision::Float64};
  format.pieces = 2;  // x: points 0..3 and 3..6
  io::write_image_frame(dir, "parallel", image, format);
  const auto expect = [&](const std::string& from, const std::string& to, const std::string& message) {
    const std::string e = error_of(dir, from, to);
    EXPECT_NE(e.find("broken.pvti"), std::string::npos) << e;
    EXPECT_NE(e.find(message), std::string::npos) << from << " → " << to << ": " << e;
  };
  expect("    <Piece Extent=\"3 6 0 2 0 0\" Source=\"parallel/parallel_1.vti\"/>\n", "", "fewer than the WholeExtent");
  expect("Extent=\"3 6 0 2 0 0\"", "Extent=\"3 7 0 2 0 0\"", "outside the WholeExtent");
  expect("Extent=\"3 6 0 2 0 0\"", "Extent=\"4 6 0 2 0 0\"", "values for its Extent");
  expect("Source=\"parallel/parallel_1.vti\"", "Source=\"../parallel_1.vti\"", "next to or below the .pvti");
  expect("Source=\"parallel/parallel_1.vti\"", "Source=\"broken.pvti\"", "expected a .vti file");
  expect("Source=\"parallel/parallel_1.vti\"", "Source=\"parallel/missing.vti\"", "cannot open");
  expect("WholeExtent=\"0 6 0 2 0 0\"", "WholeExtent=\"0 6 0 2 0 x\"", "six whole numbers");
  EXPECT_EQ(error_of(dir, "GhostLevel", "GhostLevel"), "accepted") << "the unbroken summary";
}

}  // namespace
