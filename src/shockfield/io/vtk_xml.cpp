#include "shockfield/io/vtk_xml.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>
#include <type_traits>

#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/vtk_zlib.hpp"

namespace shockfield::io {

namespace {

// The DataArray tags of one file and, for the appended encodings, the blocks of its
// <AppendedData> section (each array at its `offset` after the '_'). The blocks are written to the
// file as separate parts (io::replace_file), so a frame of tens of MB is not copied again.
class ArrayWriter {
 public:
  ArrayWriter(std::ostringstream& xml, VtkFormat format) : xml_(xml), format_(format) {}

  /// A point-data array: Int32 if categorical, else reals in the file's precision.
  void data(const VtkArray& a) {
    if (!a.integer) return reals(a.name, a.components, a.values, a.units);
    std::vector<std::int32_t> labels(a.values.size());
    for (std::size_t i = 0; i < labels.size(); ++i) labels[i] = static_cast<std::int32_t>(a.values[i]);
    array(data_array_type(a, format_.precision), a.name, a.components, labels, a.units);
  }
  void reals(const std::string& name, int components, const std::vector<double>& v, const std::string& units) {
    if (format_.precision == VtkPrecision::Float64) return array(real_type(format_.precision), name, components, v, units);
    const std::vector<float> single(v.begin(), v.end());
    array(real_type(format_.precision), name, components, single, units);
  }
  template <class T>
  void array(const char* type, const std::string& name, int components, const std::vector<T>& v,
             const std::string& units = "") {
    std::string tag = fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"{}\"",
                                  type, name, components, appended() ? "appended" : format_name());
    if (appended()) tag += fmt::format(" offset=\"{}\"", offset_);
    if (!units.empty()) tag += fmt::format(" units=\"{}\"", units);
    const std::uint64_t bytes = v.size() * sizeof(T);
    const auto* data = reinterpret_cast<const char*>(v.data());
    if (appended()) {
      xml_ << tag << "/>\n";
      std::string block;
      if (format_.encoding == VtkEncoding::Zlib) {
        block = vtk_zlib_compress(data, bytes);
      } else {  // the UInt64 byte count, then the values
        block.reserve(sizeof bytes + bytes);
        block.append(reinterpret_cast<const char*>(&bytes), sizeof bytes).append(data, bytes);
      }
      offset_ += block.size();
      blocks_.push_back(std::move(block));
      return;
    }
    xml_ << tag << ">\n";
    if (format_.encoding == VtkEncoding::Base64) {
      // VTK's uncompressed inline binary: the UInt64 byte count and the raw values, each base64-encoded.
      xml_ << base64(reinterpret_cast<const unsigned char*>(&bytes), sizeof bytes)
           << base64(reinterpret_cast<const unsigned char*>(data), bytes) << "\n";
    } else {
      for (std::size_t i = 0; i < v.size(); ++i)  // shortest text that reads back to the same value
        xml_ << fmt::format("{}", v[i]) << ((i % 9 == 8 || i + 1 == v.size()) ? '\n' : ' ');
    }
    xml_ << "        </DataArray>\n";
  }

  /// The <VTKFile> start tag for a dataset of `type`.
  std::string file_tag(const char* type) const {
    return fmt::format("<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"{}>\n",
                       type, format_.encoding == VtkEncoding::Zlib ? " compressor=\"vtkZLibDataCompressor\"" : "");
  }
  /// Writes the file atomically: the XML so far, the <AppendedData> section if any, </VTKFile>.
  void write(const std::filesystem::path& file) const {
    const std::string xml = xml_.str();
    std::vector<std::string_view> parts{xml};
    if (appended()) {
      parts.push_back("  <AppendedData encoding=\"raw\">\n   _");
      parts.insert(parts.end(), blocks_.begin(), blocks_.end());
      parts.push_back("\n  </AppendedData>\n");
    }
    parts.push_back("</VTKFile>\n");
    replace_file(file, parts);
  }

 private:
  bool appended() const { return format_.encoding == VtkEncoding::Raw || format_.encoding == VtkEncoding::Zlib; }
  const char* format_name() const { return format_.encoding == VtkEncoding::Ascii ? "ascii" : "binary"; }
  std::ostringstream& xml_;
  VtkFormat format_;
  std::vector<std::string> blocks_;
  std::size_t offset_ = 0;
};

// Each point-data array holds `points` tuples and each cell-data array `cells` (RunError naming
// the file and the array otherwise).
void require_array_lengths(const std::filesystem::path& file, const std::vector<VtkArray>& point_data,
                           std::size_t points, const std::vector<VtkArray>& cell_data, std::size_t cells) {
  for (const auto& [arrays, count, what] : {std::tuple{&point_data, points, "points"},
                                            std::tuple{&cell_data, cells, "cells"}})
    for (const VtkArray& a : *arrays)
      if (a.values.size() != count * static_cast<std::size_t>(a.components))
        throw RunError(fmt::format("{}: array '{}' has {} values for {} {}", file.string(), a.name, a.values.size(),
                                   count, what));
}

}  // namespace

std::string base64(const unsigned char* data, std::size_t size) {
  static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t b0 = data[i], b1 = i + 1 < size ? data[i + 1] : 0u, b2 = i + 2 < size ? data[i + 2] : 0u;
    const std::uint32_t n = (b0 << 16) | (b1 << 8) | b2;
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < size ? table[(n >> 6) & 63] : '=';
    out += i + 2 < size ? table[n & 63] : '=';
  }
  return out;
}

std::string length_units_attribute(const VtkImage& image) {
  return image.length_units.empty() ? "" : fmt::format(" length_units=\"{}\"", image.length_units);
}

const char* real_type(VtkPrecision precision) { return precision == VtkPrecision::Float64 ? "Float64" : "Float32"; }

const char* data_array_type(const VtkArray& a, VtkPrecision precision) {
  return a.integer ? "Int32" : real_type(precision);
}

VtkExtent VtkExtent::of(const std::array<std::size_t, 3>& points) {
  return {{0, 0, 0}, {points[0] - 1, points[1] - 1, points[2] - 1}};
}

std::string VtkExtent::text() const {
  return fmt::format("{} {} {} {} {} {}", lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
}

void write_vti(const std::filesystem::path& file, const VtkImage& image, VtkFormat format) {
  const VtkExtent whole = VtkExtent::of(image.points);
  write_vti_piece(file, image, format, whole, whole);
}

void write_vti_piece(const std::filesystem::path& file, const VtkImage& image, VtkFormat format, const VtkExtent& piece,
                     const VtkExtent& whole) {
  if (piece.points() != image.points)
    throw RunError(fmt::format("{}: piece extent {} for an image of {}×{}×{} points", file.string(), piece.text(),
                               image.points[0], image.points[1], image.points[2]));
  std::ostringstream out;
  ArrayWriter arrays(out, format);
  const auto& n = image.points;
  // VTK's cell count: n − 1 per axis, one layer along an axis of a single point.
  const std::size_t cells =
      (std::max<std::size_t>(n[0], 2) - 1) * (std::max<std::size_t>(n[1], 2) - 1) * (std::max<std::size_t>(n[2], 2) - 1);
  require_array_lengths(file, image.point_data, n[0] * n[1] * n[2], image.cell_data, cells);
  out << "<?xml version=\"1.0\"?>\n"
      << arrays.file_tag("ImageData")
      << fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{} {} {}\" Spacing=\"{} {} {}\"{}>\n",
                     whole.text(), image.origin[0], image.origin[1], image.origin[2], image.spacing[0], image.spacing[1],
                     image.spacing[2], length_units_attribute(image))
      << fmt::format("    <Piece Extent=\"{}\">\n", piece.text()) << "      <PointData>\n";
  for (const VtkArray& a : image.point_data) arrays.data(a);
  if (!image.hidden_points.empty()) {
    if (image.hidden_points.size() != n[0] * n[1] * n[2])
      throw RunError(fmt::format("{}: {} hidden-point flags for {} points", file.string(), image.hidden_points.size(),
                                 n[0] * n[1] * n[2]));
    constexpr std::uint8_t kHiddenPoint = 2;  // vtkDataSetAttributes::HIDDENPOINT
    std::vector<std::uint8_t> ghost(image.hidden_points.size());
    for (std::size_t i = 0; i < ghost.size(); ++i) ghost[i] = image.hidden_points[i] ? kHiddenPoint : 0;
    arrays.array("UInt8", "vtkGhostType", 1, ghost);
  }
  out << "      </PointData>\n      <CellData>\n";
  for (const VtkArray& a : image.cell_data) arrays.data(a);
  out << "      </CellData>\n    </Piece>\n  </ImageData>\n";
  arrays.write(file);
}

void write_vtp(const std::filesystem::path& file, const std::vector<double>& xyz, const std::vector<VtkArray>& point_data,
               VtkFormat format, const std::string& position_units) {
  const std::size_t n = xyz.size() / 3;
  std::ostringstream out;
  ArrayWriter arrays(out, format);
  out << "<?xml version=\"1.0\"?>\n"
      << arrays.file_tag("PolyData")
      << "  <PolyData>\n"
      << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                     "NumberOfPolys=\"0\">\n", n, n)
      << "      <PointData>\n";
  for (const VtkArray& a : point_data) arrays.data(a);
  out << "      </PointData>\n      <Points>\n";
  arrays.reals("points", 3, xyz, position_units);
  out << "      </Points>\n      <Verts>\n";
  // One vertex cell per point: connectivity 0..n-1, offsets 1..n.
  std::vector<std::int64_t> conn(n), offs(n);
  for (std::size_t i = 0; i < n; ++i) conn[i] = static_cast<std::int64_t>(i), offs[i] = static_cast<std::int64_t>(i + 1);
  arrays.array("Int64", "connectivity", 1, conn);
  arrays.array("Int64", "offsets", 1, offs);
  out << "      </Verts>\n    </Piece>\n  </PolyData>\n";
  arrays.write(file);
}

namespace {

// Checks the cell list and array lengths of a mesh, then writes its <Points>, its cells as
// `section` (Polys or Cells: connectivity and offsets, plus the VTK cell types in a Cells section)
// and its point and cell data.
std::size_t cell_count(const VtkCells& mesh) {
  return mesh.connectivity.size() / static_cast<std::size_t>(std::max(mesh.vertices_per_cell, 1));
}

void mesh_piece(std::ostringstream& out, ArrayWriter& arrays, const std::filesystem::path& file, const VtkCells& mesh,
                const char* section) {
  const std::size_t points = mesh.xyz.size() / 3, per_cell = static_cast<std::size_t>(mesh.vertices_per_cell);
  const std::size_t cells = cell_count(mesh);
  if ((per_cell != 3 && per_cell != 4) || mesh.xyz.size() % 3 != 0 || mesh.connectivity.size() % per_cell != 0)
    throw RunError(fmt::format("{}: {} coordinates and {} cell vertices for cells of {}", file.string(),
                               mesh.xyz.size(), mesh.connectivity.size(), per_cell));
  require_array_lengths(file, mesh.point_data, points, mesh.cell_data, cells);
  out << "      <PointData>\n";
  for (const VtkArray& a : mesh.point_data) arrays.data(a);
  out << "      </PointData>\n      <CellData>\n";
  for (const VtkArray& a : mesh.cell_data) arrays.data(a);
  out << "      </CellData>\n      <Points>\n";
  arrays.reals("points", 3, mesh.xyz, mesh.position_units);
  out << "      </Points>\n" << fmt::format("      <{}>\n", section);
  arrays.array("Int64", "connectivity", 1, mesh.connectivity);
  std::vector<std::int64_t> offsets(cells);
  for (std::size_t c = 0; c < cells; ++c) offsets[c] = static_cast<std::int64_t>((c + 1) * per_cell);
  arrays.array("Int64", "offsets", 1, offsets);
  if (std::string(section) == "Cells") {
    constexpr std::uint8_t kTriangle = 5, kTetrahedron = 10;  // VTK_TRIANGLE, VTK_TETRA
    arrays.array("UInt8", "types", 1, std::vector<std::uint8_t>(cells, per_cell == 3 ? kTriangle : kTetrahedron));
  }
  out << fmt::format("      </{}>\n    </Piece>\n", section);
}

}  // namespace

void write_vtp_polygons(const std::filesystem::path& file, const VtkCells& mesh, VtkFormat format) {
  std::ostringstream out;
  ArrayWriter arrays(out, format);
  out << "<?xml version=\"1.0\"?>\n" << arrays.file_tag("PolyData") << "  <PolyData>\n"
      << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                     "NumberOfPolys=\"{}\">\n", mesh.xyz.size() / 3, cell_count(mesh));
  mesh_piece(out, arrays, file, mesh, "Polys");
  out << "  </PolyData>\n";
  arrays.write(file);
}

void write_vtu(const std::filesystem::path& file, const VtkCells& mesh, VtkFormat format) {
  std::ostringstream out;
  ArrayWriter arrays(out, format);
  out << "<?xml version=\"1.0\"?>\n" << arrays.file_tag("UnstructuredGrid") << "  <UnstructuredGrid>\n"
      << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", mesh.xyz.size() / 3, cell_count(mesh));
  mesh_piece(out, arrays, file, mesh, "Cells");
  out << "  </UnstructuredGrid>\n";
  arrays.write(file);
}

PvdSeries::PvdSeries(std::filesystem::path file, const double* keep_until, std::string time_units)
    : file_(std::move(file)), time_units_(std::move(time_units)) {
  if (keep_until && std::filesystem::exists(file_)) {
    std::ifstream in(file_);
    const std::regex entry(R"re(timestep="([^"]+)".*file="([^"]+)")re");
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, entry) && std::stod(m[1].str()) <= *keep_until)
        entries_.emplace_back(std::stod(m[1].str()), m[2].str());
  }
  write();
}

void PvdSeries::add(double time, const std::string& data_file) {
  entries_.emplace_back(time, data_file);
  write();
}

void PvdSeries::write() const {
  std::string text = fmt::format("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection{}>\n",
                                 time_units_.empty() ? "" : fmt::format(" time_units=\"{}\"", time_units_));
  for (const auto& [t, f] : entries_)
    text += fmt::format("    <DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", t, f);
  text += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(file_, text);
}

}  // namespace shockfield::io
