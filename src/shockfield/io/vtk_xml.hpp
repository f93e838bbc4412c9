#pragma once
// VTK XML writers for ParaView (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html):
// ImageData (.vti) for fields on a regular grid, PolyData (.vtp) for particles and surfaces,
// UnstructuredGrid (.vtu) for Delaunay divisions, and the .pvd
// collection that indexes a time series of either. Encodings: ASCII text; base64 "binary" (a
// UInt64 byte count, then the raw little-endian values, each base64-encoded on its own as VTK's
// writer does); appended raw binary; and appended raw binary compressed with zlib in VTK's block
// layout (io/vtk_zlib) — ParaView's own default. Real arrays are Float64 or Float32 (VtkFormat);
// an array's unit goes into its DataArray tag as units="…" (VTK ignores attributes it does not
// know, so ParaView opens the files as usual). Every encoding reads back through
// analysis/field_reader. NaN marks a grid point without material (analyze reads it as a void cell).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::io {

enum class VtkEncoding { Ascii, Base64, Raw, Zlib };
enum class VtkPrecision { Float64, Float32 };

/// How arrays are stored; built from an encoding alone, real arrays are Float64.
struct VtkFormat {
  VtkFormat(VtkEncoding e = VtkEncoding::Ascii, VtkPrecision p = VtkPrecision::Float64) : encoding(e), precision(p) {}
  VtkEncoding encoding;
  VtkPrecision precision;
  /// Pieces per frame ([output] vtk_pieces): 1 writes one .vti/.vtp; more write a .pvti/.pvtp
  /// over that many piece files (io/vtk_pieces).
  int pieces = 1;
};

/// The case-file spelling of an encoding: "ascii", "base64", "raw", "zlib".
constexpr const char* encoding_name(VtkEncoding e) {
  switch (e) {
    case VtkEncoding::Ascii: return "ascii";
    case VtkEncoding::Base64: return "base64";
    case VtkEncoding::Raw: return "raw";
    case VtkEncoding::Zlib: return "zlib";
  }
  return "?";
}

struct VtkArray {
  std::string name;
  int components = 1;          ///< 1 (scalar), 3 (vector) or 9 (tensor, row-major)
  std::vector<double> values;  ///< components × count, interleaved
  std::string units{};         ///< SI unit ("Pa", "m/s", "1" for a number); empty: not written
  /// A categorical array (material, body, grain): written as Int32 whatever the precision, so
  /// ParaView offers it for categorical colouring and thresholds compare exact integers.
  bool integer = false;
};

/// Point data on (nx, ny, nz) grid points and cell data on the cells between them (nx − 1 per axis
/// with more than one point, x fastest); a 2D grid has nz = 1. A cell-centred field (DBM) is cell
/// data on an (n + 1)-point extent whose origin is the lower corner of its first cell.
struct VtkImage {
  std::array<std::size_t, 3> points{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  /// The unit of origin and spacing ("m", "A", "1" for model units), written as the ImageData's
  /// (PImageData's) attribute length_units="…" (VTK ignores it; `shockfield analyze` names its
  /// columns by it, docs/conventions.md); empty: not written.
  std::string length_units{};
  std::vector<VtkArray> point_data;
  std::vector<VtkArray> cell_data{};
  /// Empty, or one flag per point: the points no material reaches. They are written as VTK's
  /// blanking array vtkGhostType (UInt8, HIDDENPOINT = 2 where set, after the other arrays), so
  /// ParaView leaves the cells that touch them out instead of painting NaN; their values stay NaN
  /// for readers that do not know the array (`shockfield analyze` reads NaN as a void cell).
  std::vector<bool> hidden_points{};
};

/// The VTK type name of an array's values in a file of `precision`: Int32 (categorical), Float32 or Float64.
const char* data_array_type(const VtkArray& a, VtkPrecision precision);
/// ` length_units="…"` for an ImageData/PImageData tag, empty when the image names no length unit.
std::string length_units_attribute(const VtkImage& image);
/// The VTK type name of real values (positions) in `precision`.
const char* real_type(VtkPrecision precision);

/// Point index range [lo, hi] per axis, VTK's Extent "x0 x1 y0 y1 z0 z1".
struct VtkExtent {
  std::array<std::size_t, 3> lo{0, 0, 0}, hi{0, 0, 0};
  /// The extent of a whole grid of `points`.
  static VtkExtent of(const std::array<std::size_t, 3>& points);
  std::array<std::size_t, 3> points() const { return {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1}; }
  std::string text() const;
  bool operator==(const VtkExtent&) const = default;
};

void write_vti(const std::filesystem::path& file, const VtkImage& image, VtkFormat format);
/// write_vti of the piece `piece` of a grid of extent `whole` (a .pvti's piece file): `image` holds
/// the piece's points and cells only, and the whole grid's origin and spacing.
void write_vti_piece(const std::filesystem::path& file, const VtkImage& image, VtkFormat format, const VtkExtent& piece,
                     const VtkExtent& whole);
/// Points (x, y, z interleaved, in `position_units`) with one vertex cell each, so every ParaView
/// representation shows them.
void write_vtp(const std::filesystem::path& file, const std::vector<double>& xyz, const std::vector<VtkArray>& point_data,
               VtkFormat format, const std::string& position_units = "m");

/// Points joined into cells of one kind: triangles of a surface (PolyData polygons) or the
/// triangles/tetrahedra of a Delaunay division (UnstructuredGrid cells).
struct VtkCells {
  std::vector<double> xyz;                    ///< x, y, z interleaved
  std::string position_units;                 ///< the coordinates' unit ("A", "m", "1")
  int vertices_per_cell = 3;                  ///< 3 (triangle) or 4 (tetrahedron)
  std::vector<std::int64_t> connectivity;     ///< vertices_per_cell point indices per cell
  std::vector<VtkArray> point_data{}, cell_data{};
};
/// A triangle surface as PolyData (.vtp) with polygons.
void write_vtp_polygons(const std::filesystem::path& file, const VtkCells& mesh, VtkFormat format);
/// Triangles or tetrahedra as an UnstructuredGrid (.vtu).
void write_vtu(const std::filesystem::path& file, const VtkCells& mesh, VtkFormat format);

/// RFC 4648 base64 of `size` bytes.
std::string base64(const unsigned char* data, std::size_t size);

/// A .pvd time-series index, rewritten (atomically) after every added frame.
class PvdSeries {
 public:
  PvdSeries() = default;
  /// Starts the index at `file`; with `keep_until` (a resumed run) the existing entries with
  /// timestep <= *keep_until are kept and the others dropped. A non-empty `time_units` ("s", "ps",
  /// "1") is written as the Collection's attribute time_units="…" (VTK ignores it; `shockfield
  /// analyze` names its time column by it).
  explicit PvdSeries(std::filesystem::path file, const double* keep_until = nullptr, std::string time_units = "");
  /// Adds a frame; `data_file` is written relative to the .pvd's folder.
  void add(double time, const std::string& data_file);
  std::size_t size() const { return entries_.size(); }

 private:
  void write() const;
  std::filesystem::path file_;
  std::string time_units_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace shockfield::io
