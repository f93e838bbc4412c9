#include "shockfield/analysis/pvti_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/analysis/vti_binary.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis {

namespace {


// The six whole numbers of an Extent attribute "x0 x1 y0 y1 z0 z1", x0 <= x1 and so on.
std::array<long long, 6> parse_extent(const std::string& text, const std::string& where) {
  std::istringstream in(text);
  std::array<long long, 6> e{};
  for (long long& v : e)
    if (!(in >> v) || v < 0 || v > (1LL << 40))
      throw InputError(fmt::format("{}: extent \"{}\": expected six whole numbers >= 0", where, text));
  std::string rest;
  if (in >> rest || e[0] > e[1] || e[2] > e[3] || e[4] > e[5])
    throw InputError(fmt::format("{}: extent \"{}\": expected x0 x1 y0 y1 z0 z1 with each low <= high", where, text));
  return e;
}

// Finite numbers of an Origin or Spacing attribute (absent: the default).
void parse_triple(const std::string& text, std::array<double, 3>& out, const std::string& where) {
  if (text.empty()) return;
  std::istringstream in(text);
  for (double& v : out)
    if (!(in >> v) || !std::isfinite(v))
      throw InputError(fmt::format("{}: \"{}\": expected three finite numbers", where, text));
}

}  // namespace

GridField read_pvti(const std::string& path, const std::string& text, const std::string& array) {
  const auto image = text.find("<PImageData");
  if (image == std::string::npos)
    throw InputError(fmt::format("{}: no <PImageData> element; expected a parallel VTK image file", path));
  const std::string_view tag = std::string_view(text).substr(image, text.find('>', image) - image);
  const std::array<long long, 6> whole = parse_extent(xml_attribute(tag, "WholeExtent"), path + " WholeExtent");
  // The array: the one named, else the first of one component, as in a .vti.
  std::string name, units;
  bool cell = false;
  for (auto pos = text.find("<PDataArray", image); pos != std::string::npos && name.empty();
       pos = text.find("<PDataArray", pos + 1)) {
    const std::string_view da = std::string_view(text).substr(pos, text.find('>', pos) - pos);
    const std::string components = xml_attribute(da, "NumberOfComponents");
    if (array.empty() ? (components.empty() || components == "1") : xml_attribute(da, "Name") == array) {
      name = xml_attribute(da, "Name");
      units = xml_attribute(da, "units");
      const auto cell_pos = text.rfind("<PCellData", pos), point_pos = text.rfind("<PPointData", pos);
      cell = cell_pos != std::string::npos && cell_pos > image && (point_pos == std::string::npos || cell_pos > point_pos);
    }
  }
  if (name.empty())
    throw InputError(fmt::format("{}: no {}", path,
                                 array.empty() ? "scalar PDataArray (one component)" : fmt::format("PDataArray named '{}'", array)));
  // Whole and piece sizes in values: points, or cells (n − 1, one layer along an axis of one point).
  const auto size = [&](const std::array<long long, 6>& e, std::size_t a) {
    const auto points = static_cast<std::size_t>(e[2 * a + 1] - e[2 * a] + 1);
    return cell ? std::max<std::size_t>(points, 2) - 1 : points;
  };
  GridField f;
  f.units = units;
  f.length_units = xml_attribute(tag, "length_units");
  for (std::size_t a = 0; a < 3; ++a) f.n[a] = size(whole, a);
  parse_triple(xml_attribute(tag, "Origin"), f.origin, path + " Origin");
  parse_triple(xml_attribute(tag, "Spacing"), f.spacing, path + " Spacing");
  std::vector<std::pair<std::array<long long, 6>, GridField>> pieces;
  std::size_t read = 0;
  for (auto pos = text.find("<Piece", image); pos != std::string::npos; pos = text.find("<Piece", pos + 1)) {
    const std::string_view piece_tag = std::string_view(text).substr(pos, text.find('>', pos) - pos);
    const std::string source = xml_attribute(piece_tag, "Source"), where = fmt::format("{}: piece '{}'", path, source);
    const std::array<long long, 6> e = parse_extent(xml_attribute(piece_tag, "Extent"), where);
    for (std::size_t a = 0; a < 3; ++a)
      if (e[2 * a] < whole[2 * a] || e[2 * a + 1] > whole[2 * a + 1])
        throw InputError(fmt::format("{}: its Extent lies outside the WholeExtent", where));
    const std::string file = piece_file(path, source, ".vti", where);
    GridField piece;
    try {
      piece = read_grid_field(file, name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", where, e.what()));
    }
    for (std::size_t a = 0; a < 3; ++a)
      if (piece.n[a] != size(e, a))
        throw InputError(fmt::format("{}: {} x {} x {} values for its Extent's {} x {} x {}", where, piece.n[0],
                                     piece.n[1], piece.n[2], size(e, 0), size(e, 1), size(e, 2)));
    for (std::size_t a = 0; a < 3; ++a)  // a piece of one point along an axis of cells has none there
      if (static_cast<std::size_t>(e[2 * a] - whole[2 * a]) + piece.n[a] > f.n[a])
        throw InputError(fmt::format("{}: its Extent holds no whole cell along {}", where, "xyz"[a]));
    read += piece.size();
    pieces.emplace_back(e, std::move(piece));
  }
  const double whole_values = static_cast<double>(f.n[0]) * static_cast<double>(f.n[1]) * static_cast<double>(f.n[2]);
  if (static_cast<double>(read) < whole_values)  // before allocating the whole grid: the pieces bound its size
    throw InputError(fmt::format("{}: the pieces hold {} values, fewer than the WholeExtent's {}", path, read, whole_values));
  f.values.assign(f.size(), 0.0);
  f.is_void.assign(f.size(), 0);
  std::vector<std::uint8_t> covered(f.size(), 0);
  for (const auto& [e, piece] : pieces) {
    std::array<std::size_t, 3> lo{};  // the piece's first value in the whole grid
    for (std::size_t a = 0; a < 3; ++a)
      lo[a] = static_cast<std::size_t>(e[2 * a] - whole[2 * a]);
    for (std::size_t k = 0; k < piece.n[2]; ++k)
      for (std::size_t j = 0; j < piece.n[1]; ++j)
        for (std::size_t i = 0; i < piece.n[0]; ++i) {
          const std::size_t to = f.index(lo[0] + i, lo[1] + j, lo[2] + k), from = piece.index(i, j, k);
          f.values[to] = piece.values[from];
          f.is_void[to] = piece.void_at(from);
          covered[to] = 1;
        }
  }
  if (const auto gap = std::find(covered.begin(), covered.end(), 0); gap != covered.end())
    throw InputError(fmt::format("{}: no piece holds value {} of the WholeExtent", path, gap - covered.begin()));
  return f;
}

}  // namespace shockfield::analysis
