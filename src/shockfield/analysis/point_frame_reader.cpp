#include "shockfield/analysis/point_frame_reader.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "shockfield/analysis/vti_binary.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/unit_names.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/io/vtk_zlib.hpp"

namespace shockfield::analysis {
namespace {

namespace fs = std::filesystem;

std::string_view tag_at(std::string_view text, std::size_t pos) { return text.substr(pos, text.find('>', pos) - pos); }

// `count` whitespace-separated numbers of an ascii DataArray's body.
std::vector<double> ascii_values(std::string_view body, std::size_t count, const std::string& where) {
  std::vector<double> values;
  const char* p = body.data();
  const char* end = body.data() + body.size();
  while (values.size() < count) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    double v = 0.0;
    const auto [next, error] = std::from_chars(p, end, v);
    if (p == end || error != std::errc())
      throw InputError(fmt::format("{}: {} coordinates expected, {} read before '{}'", where, count, values.size(),
                                   std::string(p, std::min<std::size_t>(end - p, 16))));
    values.push_back(v), p = next;
  }
  return values;
}

// The values of the DataArray whose start tag is at `pos` of `markup` (in `text`): `count` of them.
std::vector<double> array_values(const std::string& text, std::string_view markup, std::size_t pos, std::size_t count,
                                 const std::string& where) {
  const std::string_view da = tag_at(markup, pos);
  const std::string format = xml_attribute(da, "format"), name = xml_attribute(da, "Name");
  const std::size_t body = markup.find('>', pos) + 1;
  const VtiBinary b{text, where, name, xml_attribute(da, "type")};
  std::vector<double> values;
  if (format == "ascii") {
    values = ascii_values(markup.substr(body, markup.find("</DataArray>", body) - body), count, where);
  } else if (format == "binary") {
    values = b.inline_values(body, count);
  } else if (format == "appended") {
    double offset = -1.0;
    const std::string o = xml_attribute(da, "offset");
    std::from_chars(o.data(), o.data() + o.size(), offset);
    values = b.appended_values(offset, count);
  } else {
    throw InputError(fmt::format("{}: DataArray '{}' has format=\"{}\"; expected ascii, binary or appended", where,
                                 name, format));
  }
  for (const double v : values)
    if (!std::isfinite(v))
      throw InputError(fmt::format("{}: DataArray '{}' holds {}; expected finite numbers", where, name, v));
  return values;
}

// `value` (a unit) of every piece must be the first piece's.
void require_same(std::string& first, const std::string& value, std::size_t piece, const char* what,
                  const std::string& where) {
  if (piece > 1 && value != first)
    throw InputError(fmt::format("{}: {} in '{}', the first piece's in '{}'", where, what, value, first));
  first = value;
}

// The points (and the point array `array`, if named) of a .vtp's every <Piece>, appended to `frame`.
void read_vtp(const std::string& path, const std::string& text, const std::string& array, PointFrame& frame) {
  const std::string_view markup = std::string_view(text).substr(0, text.find("<AppendedData"));
  if (markup.find("<PolyData") == std::string_view::npos)
    throw InputError(fmt::format("{}: no <PolyData> element; expected a VTK XML PolyData file (.vtp)", path));
  const auto vtkfile = markup.find("<VTKFile");
  const bool compressed =
      vtkfile != std::string_view::npos && !xml_attribute(tag_at(markup, vtkfile), "compressor").empty();
  std::size_t pieces = 0;
  for (auto piece = markup.find("<Piece"); piece != std::string_view::npos; piece = markup.find("<Piece", piece + 1)) {
    const std::string where = fmt::format("{}: piece {}", path, ++pieces);
    const std::string n_text = xml_attribute(tag_at(markup, piece), "NumberOfPoints");
    std::size_t n = 0;
    if (const auto [end, error] = std::from_chars(n_text.data(), n_text.data() + n_text.size(), n);
        n_text.empty() || error != std::errc() || end != n_text.data() + n_text.size())
      throw InputError(fmt::format("{}: NumberOfPoints=\"{}\"; expected a whole number >= 0", where, n_text));
    // Every coordinate takes at least a byte (zlib: packs at most kZlibMaxExpansion into one).
    if (static_cast<double>(n) * 3.0 > static_cast<double>(text.size()) * (compressed ? io::kZlibMaxExpansion : 1))
      throw InputError(fmt::format("{}: {} points cannot fit in a file of {} bytes", where, n, text.size()));
    const auto points = markup.find("<Points", piece), next_piece = markup.find("<Piece", piece + 1);
    const auto xyz_array = markup.find("<DataArray", points);
    if (points == std::string_view::npos || xyz_array == std::string_view::npos || xyz_array > next_piece)
      throw InputError(fmt::format("{}: no <Points> <DataArray>", where));
    const std::string_view da = tag_at(markup, xyz_array);
    if (const std::string nc = xml_attribute(da, "NumberOfComponents"); nc != "3")
      throw InputError(fmt::format("{}: the Points array has NumberOfComponents=\"{}\"; expected 3", where, nc));
    require_same(frame.position_units, xml_attribute(da, "units"), pieces, "points", where);
    const std::vector<double> xyz = array_values(text, markup, xyz_array, 3 * n, where);
    frame.xyz.insert(frame.xyz.end(), xyz.begin(), xyz.end());
    if (array.empty()) continue;
    // The named array of one component in this piece's <PointData>.
    const auto data = markup.find("<PointData", piece), data_end = markup.find("</PointData>", data);
    auto pos = markup.find("<DataArray", data);
    while (pos < data_end && xml_attribute(tag_at(markup, pos), "Name") != array) pos = markup.find("<DataArray", pos + 1);
    if (data > next_piece || data_end == std::string_view::npos || data_end > next_piece || pos >= data_end)
      throw InputError(fmt::format("{}: no point array named '{}'", where, array));
    if (const std::string nc = xml_attribute(tag_at(markup, pos), "NumberOfComponents"); !nc.empty() && nc != "1")
      throw InputError(fmt::format("{}: point array '{}' has {} components; expected 1", where, array, nc));
    require_same(frame.values_units, xml_attribute(tag_at(markup, pos), "units"), pieces, array.c_str(), where);
    const std::vector<double> values = array_values(text, markup, pos, n, where);
    frame.values.insert(frame.values.end(), values.begin(), values.end());
  }
  if (pieces == 0) throw InputError(fmt::format("{}: no <Piece>", path));
}

// The pieces of a .pvtp, in order.
void read_pvtp(const std::string& path, const std::string& text, const std::string& array, PointFrame& frame) {
  const auto summary = text.find("<PPolyData");
  if (summary == std::string::npos)
    throw InputError(fmt::format("{}: no <PPolyData> element; expected a parallel VTK PolyData file (.pvtp)", path));
  std::size_t pieces = 0;
  for (auto pos = text.find("<Piece", summary); pos != std::string::npos; pos = text.find("<Piece", pos + 1)) {
    const std::string source = xml_attribute(tag_at(text, pos), "Source");
    const std::string where = fmt::format("{}: piece '{}'", path, source);
    const std::string piece_path = piece_file(path, source, ".vtp", where);
    PointFrame piece;
    try {
      read_vtp(piece_path, read_whole_file(piece_path), array, piece);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", where, e.what()));
    }
    ++pieces;
    require_same(frame.position_units, piece.position_units, pieces, "points", where);
    require_same(frame.values_units, piece.values_units, pieces, array.c_str(), where);
    frame.xyz.insert(frame.xyz.end(), piece.xyz.begin(), piece.xyz.end());
    frame.values.insert(frame.values.end(), piece.values.begin(), piece.values.end());
  }
  if (pieces == 0) throw InputError(fmt::format("{}: no <Piece Source> entries", path));
}

// A LAMMPS text dump of one frame (MD's dumps/dump.<step>.lammpstrj, io/lammps_dump): its positions
// in the length unit of its ITEM: UNITS style (Å without one: LAMMPS metal units, MD's dumps), and
// the column `array`, whose unit a dump does not name.
PointFrame read_dump_frame(const std::string& path, const std::string& text, const std::string& array) {
  std::istringstream in(text);
  const auto frames = io::read_dump(in, path);
  if (frames.size() != 1)
    throw InputError(fmt::format("{}: {} frames; expected one frame per file (as MD writes its "
                                 "dumps/dump.<step>.lammpstrj)", path, frames.size()));
  const io::DumpFrame& dump = frames.front();
  PointFrame frame;
  for (const Vec3& p : dump.positions()) frame.xyz.insert(frame.xyz.end(), {p[0], p[1], p[2]});
  frame.position_units = dump.units.empty() ? "A" : units::lammps_length_unit(dump.units);
  if (frame.position_units.empty())
    throw InputError(fmt::format("{}: ITEM: UNITS '{}' is not a LAMMPS unit style ({})", path, dump.units,
                                 units::kLammpsUnitStyles));
  if (!array.empty()) frame.values = dump.column(array);
  return frame;
}

bool starts_like_dump(const std::string& text) { return text.rfind("ITEM:", 0) == 0; }

}  // namespace

bool is_point_frame_file(const std::string& path) {
  const auto ext = fs::path(path).extension();
  if (ext == ".vtp" || ext == ".pvtp") return true;
  std::ifstream in(path);
  std::string first;
  return std::getline(in, first) && starts_like_dump(first);
}

PointFrame read_point_frame(const std::string& path, const std::string& array) {
  const std::string text = read_whole_file(path);
  PointFrame frame;
  if (starts_like_dump(text))
    frame = read_dump_frame(path, text, array);
  else if (fs::path(path).extension() == ".pvtp")
    read_pvtp(path, text, array, frame);
  else
    read_vtp(path, text, array, frame);
  return frame;
}

}  // namespace shockfield::analysis
