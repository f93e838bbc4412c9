#include "shockfield/analysis/field_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

double parse_number(const std::string& token, const std::string& where) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(token, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || trim(token.substr(used)) != "")
    throw InputError(fmt::format("{}: '{}' is not a number", where, token));
  return v;
}

// Stores `value` (NaN = void) as the next cell.
void push(GridField& f, double value) {
  f.values.push_back(std::isnan(value) ? 0.0 : value);
  f.is_void.push_back(std::isnan(value) ? 1 : 0);
}

GridField read_csv(const std::string& path, std::ifstream& in) {
  GridField f;
  f.n = {0, 0, 1};
  std::size_t rows_in_slice = 0, line_no = 0, slices = 0;
  std::string line;
  bool in_slice = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = fmt::format("{}:{}", path, line_no);
    const std::string t = trim(line);
    if (!t.empty() && t[0] == '#') {
      std::istringstream c(t.substr(1));
      std::string key, eq;
      c >> key >> eq;
      if (key == "spacing") f.spacing.fill(parse_number(trim(c.str().substr(c.tellg())), where));
      if (key == "origin")
        for (auto& o : f.origin) c >> o;
      continue;
    }
    if (t.empty()) {
      if (in_slice) {
        if (slices > 0 && rows_in_slice != f.n[1])
          throw InputError(fmt::format("{}: slice {} has {} rows, the first has {}", where, slices,
                                       rows_in_slice, f.n[1]));
        f.n[1] = rows_in_slice, ++slices, rows_in_slice = 0, in_slice = false;
      }
      continue;
    }
    std::vector<double> row;
    std::stringstream cells(t);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      const std::string c = lower(trim(cell));
      row.push_back(c.empty() || c == "void" ? std::numeric_limits<double>::quiet_NaN()
                                             : parse_number(c, where));
      if (std::isnan(row.back()) && !(c.empty() || c == "void"))
        throw InputError(fmt::format("{}: NaN value; write `void` for a cell without material",
                                     where));
    }
    if (t.back() == ',') row.push_back(std::numeric_limits<double>::quiet_NaN());
    if (f.n[0] == 0) f.n[0] = row.size();
    if (row.size() != f.n[0])
      throw InputError(fmt::format("{}: {} values in this row, {} in the first row", where,
                                   row.size(), f.n[0]));
    for (double v : row) push(f, v);
    ++rows_in_slice, in_slice = true;
  }
  if (in_slice) {
    if (slices > 0 && rows_in_slice != f.n[1])
      throw InputError(fmt::format("{}: last slice has {} rows, the first has {}", path,
                                   rows_in_slice, f.n[1]));
    f.n[1] = rows_in_slice, ++slices;
  }
  f.n[2] = std::max<std::size_t>(slices, 1);
  if (f.values.empty()) f.n = {0, 0, 1};
  return f;
}

// Reads `count` whitespace-separated numbers (NaN allowed = void) from `in`.
void read_values(std::istream& in, std::size_t count, GridField& f, const std::string& path) {
  std::string token;
  for (std::size_t i = 0; i < count; ++i) {
    if (!(in >> token))
      throw InputError(fmt::format("{}: {} values expected, the data ends after {}", path, count, i));
    const std::string t = lower(token);
    push(f, t == "nan" || t == "-nan" ? std::numeric_limits<double>::quiet_NaN()
                                      : parse_number(token, path));
  }
}

GridField read_legacy_vtk(const std::string& path, std::ifstream& in, const std::string& array) {
  GridField f;
  std::array<std::size_t, 3> dims{0, 0, 0};
  std::string line, word;
  std::getline(in, line);  // # vtk DataFile Version x.x
  std::getline(in, line);  // title
  std::getline(in, line);
  if (trim(line) != "ASCII")
    throw InputError(fmt::format("{}: legacy VTK encoding '{}'; only ASCII is read (use .vti "
                                 "ascii or convert)", path, trim(line)));
  bool cell_data = false;
  while (in >> word) {
    word = lower(word);
    if (word == "dataset") {
      in >> word;
      if (lower(word) != "structured_points")
        throw InputError(fmt::format("{}: DATASET {}; expected STRUCTURED_POINTS (image data)",
                                     path, word));
    } else if (word == "dimensions") {
      in >> dims[0] >> dims[1] >> dims[2];
    } else if (word == "spacing" || word == "aspect_ratio") {
      in >> f.spacing[0] >> f.spacing[1] >> f.spacing[2];
    } else if (word == "origin") {
      in >> f.origin[0] >> f.origin[1] >> f.origin[2];
    } else if (word == "point_data" || word == "cell_data") {
      cell_data = word == "cell_data";
      std::size_t count = 0;
      in >> count;
    } else if (word == "scalars") {
      std::string name, type;
      in >> name >> type;
      std::getline(in, line);  // optional component count
      if (!trim(line).empty() && trim(line) != "1")
        throw InputError(fmt::format("{}: SCALARS {} has {} components; expected 1", path, name,
                                     trim(line)));
      in >> word >> word;  // LOOKUP_TABLE default
      for (int a = 0; a < 3; ++a)
        f.n[a] = cell_data ? std::max<std::size_t>(dims[a], 2) - 1 : std::max<std::size_t>(dims[a], 1);
      const std::size_t count = f.n[0] * f.n[1] * f.n[2];
      f.values.clear(), f.is_void.clear();
      read_values(in, count, f, path);
      if (array.empty() || name == array) return f;
    }
  }
  throw InputError(fmt::format("{}: no SCALARS array{}", path,
                               array.empty() ? "" : fmt::format(" named '{}'", array)));
}

// Value of attribute `key` in an XML start tag.
std::string attribute(const std::string& tag, const std::string& key) {
  const auto p = tag.find(" " + key + "=\"");
  if (p == std::string::npos) return "";
  const auto b = p + key.size() + 3;
  return tag.substr(b, tag.find('"', b) - b);
}

GridField read_vti(const std::string& path, std::ifstream& in, const std::string& array) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto image = text.find("<ImageData");
  if (image == std::string::npos)
    throw InputError(fmt::format("{}: no <ImageData> element; expected a VTK XML image file", path));
  const std::string tag = text.substr(image, text.find('>', image) - image);
  std::istringstream extent(attribute(tag, "WholeExtent"));
  std::array<long, 6> e{};
  for (auto& v : e) extent >> v;
  GridField f;
  std::istringstream(attribute(tag, "Origin")) >> f.origin[0] >> f.origin[1] >> f.origin[2];
  std::istringstream(attribute(tag, "Spacing")) >> f.spacing[0] >> f.spacing[1] >> f.spacing[2];
  for (std::size_t pos = text.find("<DataArray", image); pos != std::string::npos;
       pos = text.find("<DataArray", pos + 1)) {
    const std::string da = text.substr(pos, text.find('>', pos) - pos);
    if (!array.empty() && attribute(da, "Name") != array) continue;
    if (attribute(da, "format") != "ascii")
      throw InputError(fmt::format("{}: DataArray '{}' has format=\"{}\"; only ascii is read",
                                   path, attribute(da, "Name"), attribute(da, "format")));
    const std::string nc = attribute(da, "NumberOfComponents");
    if (!nc.empty() && nc != "1")
      throw InputError(fmt::format("{}: DataArray '{}' has {} components; expected 1", path,
                                   attribute(da, "Name"), nc));
    const auto cell_pos = text.rfind("<CellData", pos), point_pos = text.rfind("<PointData", pos);
    const bool cell = cell_pos != std::string::npos &&
                      (point_pos == std::string::npos || cell_pos > point_pos);
    for (int a = 0; a < 3; ++a) {
      const auto points = static_cast<std::size_t>(e[2 * a + 1] - e[2 * a] + 1);
      f.n[a] = cell ? std::max<std::size_t>(points, 2) - 1 : points;
    }
    const auto body = text.find('>', pos) + 1;
    std::istringstream values(text.substr(body, text.find("</DataArray>", body) - body));
    read_values(values, f.size(), f, path);
    return f;
  }
  throw InputError(fmt::format("{}: no DataArray{}", path,
                               array.empty() ? "" : fmt::format(" named '{}'", array)));
}

}  // namespace

GridField read_grid_field(const std::string& path, const std::string& array) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open", path));
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  GridField f;
  if (ext == ".csv" || ext == ".txt") f = read_csv(path, in);
  else if (ext == ".vtk") f = read_legacy_vtk(path, in, array);
  else if (ext == ".vti") f = read_vti(path, in, array);
  else
    throw InputError(fmt::format("{}: unknown field format '{}'; expected .csv, .txt, .vtk "
                                 "(legacy ASCII STRUCTURED_POINTS) or .vti (XML ImageData, ascii)",
                                 path, ext));
  if (f.void_count() == 0) f.is_void.clear();
  validate(f, path);
  return f;
}

}  // namespace shockfield::analysis
