// Parallel VTK pieces (io/vtk_pieces): the piece extents tile the whole extent in slabs of whole
// cells, neighbours sharing the boundary plane of points that VTK's point data needs; each
// piece holds exactly the values of its points and cells; one piece is the single file byte for
// byte; more pieces than particles leave valid empty pieces. VTK itself reads the pieces back in
// tests/cli/vtk_pieces.sh.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/io/vtk_pieces.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;
using Index3 = std::array<std::size_t, 3>;

fs::path fresh_dir(const char* name) {
  const fs::path dir = shockfield::testing::scratch_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t cells_along(std::size_t points) { return points > 1 ? points - 1 : 1; }

// Every point and every cell of the grid lies in some piece, each cell in exactly one; the cut
// axis is the one with the most cells; the other axes span the whole extent; neighbours share one
// plane of points; no piece is without cells.
void expect_tiling(const Index3& n, int pieces) {
  SCOPED_TRACE(fmt::format("{}×{}×{} points, {} pieces", n[0], n[1], n[2], pieces));
  const std::vector<io::VtkExtent> extents = io::image_piece_extents(n, pieces);
  const std::size_t most_cells = std::max({n[0], n[1], n[2]}) - 1;
  EXPECT_EQ(extents.size(), std::max<std::size_t>(1, std::min<std::size_t>(most_cells, static_cast<std::size_t>(pieces))));
  std::size_t cut = 2;  // the axis of the most points, the slowest of equal ones
  for (std::size_t d : {1u, 0u})
    if (n[d] > n[cut]) cut = d;
  std::vector<int> point_hits(n[0] * n[1] * n[2], 0), cell_hits(cells_along(n[0]) * cells_along(n[1]) * cells_along(n[2]), 0);
  for (std::size_t p = 0; p < extents.size(); ++p) {
    const io::VtkExtent& e = extents[p];
    for (std::size_t d = 0; d < 3; ++d) {
      ASSERT_LE(e.lo[d], e.hi[d]);
      ASSERT_LT(e.hi[d], n[d]);
      if (n[d] > 1) {
        EXPECT_LT(e.lo[d], e.hi[d]) << "a piece without cells along axis " << d;
      }
    }
    for (std::size_t d = 0; d < 3; ++d)
      if (d != cut) {
        EXPECT_TRUE(e.lo[d] == 0 && e.hi[d] == n[d] - 1) << "piece " << p << " is cut along axis " << d;
      }
    if (p > 0) {
      EXPECT_EQ(e.lo[cut], extents[p - 1].hi[cut]) << "pieces " << p - 1 << " and " << p << " share no plane";
    }
    for (std::size_t k = e.lo[2]; k <= e.hi[2]; ++k)
      for (std::size_t j = e.lo[1]; j <= e.hi[1]; ++j)
        for (std::size_t i = e.lo[0]; i <= e.hi[0]; ++i) ++point_hits[(k * n[1] + j) * n[0] + i];
    // The piece's cells: [lo, hi) along an axis of several points, the one layer otherwise.
    Index3 c_lo{}, c_hi{};
    for (std::size_t d = 0; d < 3; ++d) c_lo[d] = n[d] > 1 ? e.lo[d] : 0, c_hi[d] = n[d] > 1 ? e.hi[d] : 1;
    for (std::size_t k = c_lo[2]; k < c_hi[2]; ++k)
      for (std::size_t j = c_lo[1]; j < c_hi[1]; ++j)
        for (std::size_t i = c_lo[0]; i < c_hi[0]; ++i) ++cell_hits[(k * cells_along(n[1]) + j) * cells_along(n[0]) + i];
  }
  EXPECT_EQ(extents.front().lo, (Index3{0, 0, 0}));
  EXPECT_EQ(extents.back().hi, (Index3{n[0] - 1, n[1] - 1, n[2] - 1}));
  for (int h : point_hits) ASSERT_GE(h, 1) << "a point in no piece";
  for (int h : cell_hits) ASSERT_EQ(h, 1) << "a cell in none or in two pieces";
}

TEST(VtkPieces, ExtentsTileTheWholeExtentWithSharedBoundaryPoints) {
  for (const Index3& n : {Index3{9, 1, 1}, Index3{5, 4, 1}, Index3{4, 6, 3}, Index3{6, 6, 6}, Index3{3, 2, 7}})
    for (int pieces : {1, 2, 3, 5, 64}) expect_tiling(n, pieces);
}

TEST(VtkPieces, CutAxisHasTheMostCellsAndTheSlowestOfEqualOnes) {
  // y has 5 cells: cells [0, 2) and [2, 5), points 0..2 and 2..5.
  EXPECT_EQ(io::image_piece_extents({4, 6, 3}, 2)[0].hi, (Index3{3, 2, 2}));
  EXPECT_EQ(io::image_piece_extents({4, 6, 3}, 2)[1].lo, (Index3{0, 2, 0}));
  EXPECT_EQ(io::image_piece_extents({6, 6, 6}, 2)[0].hi, (Index3{5, 5, 2}));  // equal axes: z, the slowest
  EXPECT_EQ(io::image_piece_extents({1, 1, 1}, 3).size(), 1u);                 // a single point: one piece
  EXPECT_THROW(io::image_piece_extents({4, 4, 1}, 0), RunError);
}

TEST(VtkPieces, PieceHoldsTheValuesOfItsPointsAndCells) {
  io::VtkImage image;
  image.points = {4, 5, 3};
  const std::size_t points = 4 * 5 * 3, cells = 3 * 4 * 2;
  std::vector<double> index(points), vector(3 * points), cell_index(cells);
  std::iota(index.begin(), index.end(), 0.0);
  std::iota(vector.begin(), vector.end(), 0.0);
  std::iota(cell_index.begin(), cell_index.end(), 0.0);
  image.point_data = {{"index", 1, index, "1"}, {"vector", 3, vector, "m/s"}};
  image.cell_data = {{"cell", 1, cell_index, "1", true}};
  image.hidden_points.assign(points, false);
  image.hidden_points[37] = true;
  for (const io::VtkExtent& e : io::image_piece_extents(image.points, 3)) {
    const io::VtkImage piece = io::image_piece(image, e);
    const Index3 n = e.points();
    ASSERT_EQ(piece.points, n);
    ASSERT_EQ(piece.point_data[1].values.size(), 3 * n[0] * n[1] * n[2]);
    ASSERT_EQ(piece.cell_data[0].values.size(), (n[0] - 1) * (n[1] - 1) * (n[2] - 1));
    EXPECT_EQ(piece.point_data[1].units, "m/s");
    EXPECT_TRUE(piece.cell_data[0].integer);
    std::size_t q = 0, c = 0;
    for (std::size_t k = 0; k < n[2]; ++k)
      for (std::size_t j = 0; j < n[1]; ++j)
        for (std::size_t i = 0; i < n[0]; ++i, ++q) {
          const std::size_t global = ((e.lo[2] + k) * 5 + e.lo[1] + j) * 4 + e.lo[0] + i;
          EXPECT_EQ(piece.point_data[0].values[q], static_cast<double>(global));
          EXPECT_EQ(piece.point_data[1].values[3 * q + 2], static_cast<double>(3 * global + 2));
          EXPECT_EQ(piece.hidden_points[q], global == 37);
          if (i + 1 < n[0] && j + 1 < n[1] && k + 1 < n[2]) {
            EXPECT_EQ(piece.cell_data[0].values[c++], static_cast<double>(((e.lo[2] + k) * 4 + e.lo[1] + j) * 3 + e.lo[0] + i));
          }
        }
  }
  io::VtkExtent thin = io::VtkExtent::of(image.points);
  thin.hi[2] = 0;  // a plane of a 3D grid has no cells of its own
  EXPECT_THROW(io::image_piece(image, thin), RunError);
}

TEST(VtkPieces, OnePieceIsTheSingleFileByteForByte) {
  const fs::path dir = fresh_dir("shockfield_vtk_pieces_single");
  io::VtkImage image;
  image.points = {3, 2, 1};
  image.point_data = {{"rho", 1, {1, 2, 3, 4, 5, 6}, "kg/m3"}};
  const io::VtkFormat format{io::VtkEncoding::Zlib, io::VtkPrecision::Float32};
  EXPECT_EQ(io::write_image_frame(dir, "grid_1", image, format), "grid_1.vti");
  io::write_vti(dir / "direct.vti", image, format);
  EXPECT_EQ(read_text(dir / "grid_1.vti"), read_text(dir / "direct.vti"));
  const std::vector<double> xyz{0, 0, 0, 1, 0, 0};
  EXPECT_EQ(io::write_points_frame(dir, "points_1", xyz, {{"m", 1, {1, 2}, "kg"}}, format), "points_1.vtp");
  io::write_vtp(dir / "direct.vtp", xyz, {{"m", 1, {1, 2}, "kg"}}, format);
  EXPECT_EQ(read_text(dir / "points_1.vtp"), read_text(dir / "direct.vtp"));
  EXPECT_FALSE(fs::exists(dir / "grid_1")) << "one piece wrote a pieces folder";
}

TEST(VtkPieces, MorePiecesThanParticlesLeaveEmptyValidPieces) {
  const fs::path dir = fresh_dir("shockfield_vtk_pieces_empty");
  io::VtkFormat format{io::VtkEncoding::Raw, io::VtkPrecision::Float64};
  format.pieces = 3;
  const std::vector<double> xyz{0, 0, 0, 1, 2, 3};
  EXPECT_EQ(io::write_points_frame(dir, "sub/points_7", xyz, {{"grain", 1, {4, 9}, "1", true}}, format),
            "sub/points_7.pvtp");
  const std::string summary = read_text(dir / "sub/points_7.pvtp");
  EXPECT_NE(summary.find("<PDataArray type=\"Int32\" Name=\"grain\" NumberOfComponents=\"1\" units=\"1\"/>"),
            std::string::npos) << summary;
  EXPECT_NE(summary.find("<PDataArray type=\"Float64\" Name=\"points\" NumberOfComponents=\"3\" units=\"m\"/>"),
            std::string::npos) << summary;
  std::size_t total = 0;
  for (int p = 0; p < 3; ++p) {
    const std::string source = fmt::format("points_7/points_7_{}.vtp", p);
    EXPECT_NE(summary.find(fmt::format("<Piece Source=\"{}\"/>", source)), std::string::npos) << source;
    const std::string piece = read_text(dir / "sub" / source);
    const auto at = piece.find("NumberOfPoints=\"");
    ASSERT_NE(at, std::string::npos);
    total += std::stoul(piece.substr(at + 16));
  }
  EXPECT_EQ(total, 2u);
  EXPECT_NE(read_text(dir / "sub/points_7/points_7_0.vtp").find("NumberOfPoints=\"0\""), std::string::npos)
      << "particles [0, 2/3) should be none";
}

}  // namespace
