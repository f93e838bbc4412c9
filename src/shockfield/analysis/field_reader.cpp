#include "shockfield/analysis/field_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include "shockfield/analysis/pvti_reader.hpp"
#include "shockfield/analysis/vti_binary.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/io/vtk_zlib.hpp"

namespace shockfield::analysis {
namespace {

constexpr double kVoid = std::numeric_limits<double>::quiet_NaN();

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r") - b + 1));
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
  if (std::isinf(v)) throw InputError(fmt::format("{}: '{}' is infinite; expected a finite number", where, token));
  return v;
}

// A number that must be finite: grid geometry (origin, spacing, extents), times, offsets. NaN
// stands for a void cell only among the values.
double finite_number(const std::string& token, const std::string& where) {
  const double v = parse_number(token, where);
  if (std::isnan(v)) throw InputError(fmt::format("{}: '{}' is not a finite number", where, token));
  return v;
}

// The cell count of a grid, refused when it exceeds the bytes of the file (each value takes at
// least one): checked before anything is sized by the dimensions, which could also overflow.
std::size_t checked_cells(const std::array<std::size_t, 3>& n, std::size_t file_bytes,
                          const std::string& where) {
  const double cells = static_cast<double>(n[0]) * static_cast<double>(n[1]) * static_cast<double>(n[2]);
  if (cells > static_cast<double>(file_bytes))
    throw InputError(fmt::format("{}: a grid of {} x {} x {} values cannot fit in a file of {} bytes",
                                 where, n[0], n[1], n[2], file_bytes));
  return n[0] * n[1] * n[2];
}

// Stores `value` (NaN = void) as the next cell.
void push(GridField& f, double value) {
  f.values.push_back(std::isnan(value) ? 0.0 : value);
  f.is_void.push_back(std::isnan(value) ? 1 : 0);
}

// Whitespace-separated tokens of a text, with the line each is on (for file:line messages).
class Tokens {
 public:
  Tokens(std::string_view text, std::string path, std::size_t first_line = 1)
      : text_(text), path_(std::move(path)), line_(first_line), token_line_(first_line) {}

  /// The next token; empty at the end of the text.
  std::string next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      line_ += text_[pos_++] == '\n';
    const std::size_t start = pos_;
    if (start < text_.size()) token_line_ = line_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }
  /// The rest of the current line, trimmed; moves to the next line.
  std::string rest_of_line() {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    const std::string rest = trim(text_.substr(pos_, end - pos_));
    token_line_ = line_;
    line_ += end < text_.size(), pos_ = std::min(end + 1, text_.size());
    return rest;
  }
  /// "file:line" of the last token (or line) read.
  std::string where() const { return fmt::format("{}:{}", path_, token_line_); }
  double number(const char* what) {
    const std::string t = next();
    if (t.empty()) throw InputError(fmt::format("{}: {} expected, the file ends", where(), what));
    return finite_number(t, where());
  }
  std::size_t count(const char* what) {
    const double v = number(what);
    if (!(v >= 0.0) || v != std::floor(v) || v > 1e15)
      throw InputError(fmt::format("{}: {} is {}; expected a whole number >= 0", where(), what, v));
    return static_cast<std::size_t>(v);
  }

 private:
  std::string_view text_;
  std::string path_;
  std::size_t line_, token_line_, pos_ = 0;
};

// Reads f.size() whitespace-separated numbers (nan = void) into f.
void read_values(Tokens& in, GridField& f) {
  const std::size_t count = f.size();
  f.values.clear(), f.is_void.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const std::string token = in.next();
    if (token.empty())
      throw InputError(
          fmt::format("{}: {} values expected for {} x {} x {} cells, the data ends "
                      "after {}",
                      in.where(), count, f.n[0], f.n[1], f.n[2], i));
    const std::string t = lower(token);
    push(f, t == "nan" || t == "-nan" ? kVoid : parse_number(token, in.where()));
  }
}

GridField read_csv(const std::string& path, const std::string& text) {
  GridField f;
  f.n = {0, 0, 1};
  std::size_t rows_in_slice = 0, line_no = 0, slices = 0;
  std::istringstream in(text);
  std::string line;
  bool in_slice = false;
  const auto end_slice = [&](const std::string& where) {
    if (slices > 0 && rows_in_slice != f.n[1])
      throw InputError(fmt::format("{}: slice {} has {} rows, the first has {}", where, slices + 1,
                                   rows_in_slice, f.n[1]));
    f.n[1] = rows_in_slice, ++slices, rows_in_slice = 0, in_slice = false;
  };
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = fmt::format("{}:{}", path, line_no);
    const std::string t = trim(line);
    if (!t.empty() && t[0] == '#') {
      std::istringstream c(t.substr(1));
      std::string key, eq;
      c >> key >> eq;
      if (key == "spacing") {  // the rest of the line (tellg() is −1 once the stream has ended)
        std::string rest;
        std::getline(c, rest);
        f.spacing.fill(finite_number(trim(rest), where));
      }
      if (key == "units" || key == "length_units") {
        std::string unit;
        c >> unit;
        (key == "units" ? f.units : f.length_units) = unit;
      }
      if (key == "origin")
        for (auto& o : f.origin)
          o = finite_number(
              [&] {
                std::string s;
                c >> s;
                return s;
              }(),
              where);
      continue;
    }
    if (t.empty()) {
      if (in_slice) end_slice(where);
      continue;
    }
    std::vector<double> row;
    std::stringstream cells(t);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      const std::string c = lower(trim(cell));
      row.push_back(c.empty() || c == "void" ? kVoid : parse_number(c, where));
      if (std::isnan(row.back()) && !(c.empty() || c == "void"))
        throw InputError(
            fmt::format("{}: NaN value; write `void` for a cell without material", where));
    }
    if (t.back() == ',') row.push_back(kVoid);
    if (f.n[0] == 0) f.n[0] = row.size();
    if (row.size() != f.n[0])
      throw InputError(
          fmt::format("{}: {} values in this row, {} in the first row", where, row.size(), f.n[0]));
    for (double v : row) push(f, v);
    ++rows_in_slice, in_slice = true;
  }
  if (in_slice) end_slice(fmt::format("{}:{}", path, line_no));
  f.n[2] = std::max<std::size_t>(slices, 1);
  if (f.values.empty()) f.n = {0, 0, 1};
  return f;
}

GridField read_legacy_vtk(const std::string& path, const std::string& text,
                          const std::string& array) {
  GridField f;
  std::array<std::size_t, 3> dims{0, 0, 0};
  Tokens in(text, path);
  if (in.rest_of_line().rfind("# vtk DataFile", 0) != 0)
    throw InputError(fmt::format("{}:1: not a legacy VTK file (no '# vtk DataFile' line)", path));
  in.rest_of_line();  // title
  if (const std::string encoding = in.rest_of_line(); encoding != "ASCII")
    throw InputError(
        fmt::format("{}:3: legacy VTK encoding '{}'; only ASCII is read (save as "
                    ".vti, whose binary forms are read)",
                    path, encoding));
  bool cell_data = false;
  for (std::string word = lower(in.next()); !word.empty(); word = lower(in.next())) {
    if (word == "dataset") {
      const std::string type = in.next();
      if (lower(type) != "structured_points")
        throw InputError(fmt::format("{}: DATASET {}; expected STRUCTURED_POINTS (image data)",
                                     in.where(), type));
    } else if (word == "dimensions") {
      for (auto& d : dims) d = in.count("DIMENSIONS value");
    } else if (word == "spacing" || word == "aspect_ratio") {
      for (auto& s : f.spacing) s = in.number("SPACING value");
    } else if (word == "origin") {
      for (auto& o : f.origin) o = in.number("ORIGIN value");
    } else if (word == "point_data" || word == "cell_data") {
      cell_data = word == "cell_data";
      const std::size_t count = in.count("number of values");
      if (checked_cells(dims, text.size(), in.where()) == 0)
        throw InputError(fmt::format("{}: {} before DIMENSIONS", in.where(), word));
      for (int a = 0; a < 3; ++a)
        f.n[a] = cell_data ? std::max<std::size_t>(dims[a], 2) - 1 : dims[a];
      if (count != f.size())
        throw InputError(fmt::format("{}: {} {} for DIMENSIONS {} {} {}; expected {}", in.where(),
                                     word, count, dims[0], dims[1], dims[2], f.size()));
    } else if (word == "scalars") {
      const std::string name = in.next(), type = in.next();
      if (const std::string comps = in.rest_of_line(); !comps.empty() && comps != "1")
        throw InputError(
            fmt::format("{}: SCALARS {} has {} components; expected 1", in.where(), name, comps));
      if (lower(in.next()) != "lookup_table")
        throw InputError(fmt::format("{}: expected LOOKUP_TABLE after SCALARS", in.where()));
      in.next();  // table name
      if (f.size() == 0)
        throw InputError(fmt::format("{}: SCALARS before POINT_DATA / CELL_DATA", in.where()));
      read_values(in, f);
      if (array.empty() || name == array) return f;
    }
  }
  throw InputError(fmt::format("{}: no SCALARS array{}", path,
                               array.empty() ? "" : fmt::format(" named '{}'", array)));
}

std::size_t line_at(const std::string& text, std::size_t pos) {
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + pos, '\n'));
}

GridField read_vti(const std::string& path, const std::string& text, const std::string& array) {
  // Markup ends where raw appended data may begin.
  const std::string_view markup = std::string_view(text).substr(0, text.find("<AppendedData"));
  const auto image = markup.find("<ImageData");
  if (image == std::string::npos)
    throw InputError(
        fmt::format("{}: no <ImageData> element; expected a VTK XML image file", path));
  const auto tag = markup.substr(image, markup.find('>', image) - image);
  const auto where = [&](std::size_t pos) {
    return fmt::format("{}:{}", path, line_at(text, pos));
  };
  const std::string whole_extent = xml_attribute(tag, "WholeExtent");  // Tokens views it
  Tokens extent(whole_extent, path, line_at(text, image));
  std::array<double, 6> w{};
  for (auto& v : w) v = extent.number("WholeExtent value");
  const auto check_extent = [&](const std::array<double, 6>& x, const char* what) {
    for (int a = 0; a < 3; ++a)
      if (const double points = std::max(0.0, x[2 * a + 1] - x[2 * a] + 1);
          points > static_cast<double>(text.size()) || points != std::floor(points))
        throw InputError(fmt::format("{}: {} {} {} along {} is not a whole number of points that fits in the file",
                                     where(image), what, x[2 * a], x[2 * a + 1], "xyz"[a]));
  };
  check_extent(w, "WholeExtent");
  // A piece of a .pvti holds its own Extent within the WholeExtent (a single file: the same).
  std::array<double, 6> e = w;
  if (const auto piece = markup.find("<Piece", image); piece != std::string::npos) {
    const std::string given = xml_attribute(markup.substr(piece, markup.find('>', piece) - piece), "Extent");
    Tokens t(given, path, line_at(text, piece));
    if (!given.empty())
      for (auto& v : e) v = t.number("Piece Extent value");
    for (int a = 0; a < 3; ++a)
      if (e[2 * a] < w[2 * a] || e[2 * a + 1] > w[2 * a + 1])
        throw InputError(fmt::format("{}: Piece Extent {} {} along {} lies outside the WholeExtent {} {}", where(piece),
                                     e[2 * a], e[2 * a + 1], "xyz"[a], w[2 * a], w[2 * a + 1]));
    check_extent(e, "Piece Extent");
  }
  GridField f;
  f.length_units = xml_attribute(tag, "length_units");
  for (const auto& [key, values] : {std::pair{"Origin", &f.origin}, {"Spacing", &f.spacing}}) {
    const std::string given = xml_attribute(tag, key);
    Tokens t(given, path, line_at(text, image));
    for (double& v : *values)
      if (const std::string token = t.next(); !token.empty()) v = finite_number(token, t.where());
  }
  for (auto pos = markup.find("<DataArray", image); pos != std::string::npos;
       pos = markup.find("<DataArray", pos + 1)) {
    const auto da = markup.substr(pos, markup.find('>', pos) - pos);
    const std::string name = xml_attribute(da, "Name"), format = xml_attribute(da, "format");
    if (!array.empty() && name != array) continue;
    const std::string nc = xml_attribute(da, "NumberOfComponents");
    const bool scalar = nc.empty() || nc == "1";
    if (array.empty() && !scalar) continue;  // the first scalar array
    if (!scalar)
      throw InputError(
          fmt::format("{}: DataArray '{}' has {} components; expected 1", where(pos), name, nc));
    f.units = xml_attribute(da, "units");
    const auto cell_pos = markup.rfind("<CellData", pos),
               point_pos = markup.rfind("<PointData", pos);
    const bool cell =
        cell_pos != std::string::npos && (point_pos == std::string::npos || cell_pos > point_pos);
    for (int a = 0; a < 3; ++a) {
      const double points = std::max(0.0, e[2 * a + 1] - e[2 * a] + 1);
      f.n[a] = cell ? std::max<std::size_t>(static_cast<std::size_t>(points), 2) - 1
                    : static_cast<std::size_t>(points);
    }
    // zlib packs at most io::kZlibMaxExpansion bytes into one, so a compressed file may hold more values than bytes.
    const auto vtkfile = markup.find("<VTKFile");
    const bool compressed = vtkfile != std::string::npos &&
                            !xml_attribute(std::string_view(markup).substr(vtkfile, markup.find('>', vtkfile) - vtkfile),
                                           "compressor").empty();
    checked_cells(f.n, text.size() * (compressed ? io::kZlibMaxExpansion : 1), where(image));
    const auto body = markup.find('>', pos) + 1;
    if (format == "ascii") {
      Tokens values(markup.substr(body, markup.find("</DataArray>", body) - body), path,
                    line_at(text, body));
      read_values(values, f);
    } else {
      const VtiBinary b{text, where(pos), name, xml_attribute(da, "type")};
      std::vector<double> values;
      if (format == "binary")
        values = b.inline_values(body, f.size());
      else if (format == "appended")
        values = b.appended_values(finite_number(xml_attribute(da, "offset"), where(pos)), f.size());
      else
        throw InputError(
            fmt::format("{}: DataArray '{}' has format=\"{}\"; expected ascii, "
                        "binary or appended",
                        where(pos), name, format));
      for (const double v : values) {
        if (std::isinf(v))
          throw InputError(fmt::format("{}: DataArray '{}' holds an infinite value; expected finite "
                                       "numbers (NaN for void cells)", where(pos), name));
        push(f, v);
      }
    }
    return f;
  }
  throw InputError(fmt::format("{}: no {}", path,
                               array.empty() ? "scalar DataArray (one component)"
                                             : fmt::format("DataArray named '{}'", array)));
}

std::vector<SeriesEntry> read_pvd(const std::filesystem::path& pvd) {
  const std::string text = read_whole_file(pvd.string());
  std::vector<SeriesEntry> out;
  const auto collection = text.find("<Collection");
  const std::string time_units =
      collection == std::string::npos ? "" : xml_attribute(std::string_view(text).substr(collection, text.find('>', collection) - collection), "time_units");
  for (auto pos = text.find("<DataSet"); pos != std::string::npos;
       pos = text.find("<DataSet", pos + 1)) {
    const std::string tag = text.substr(pos, text.find('>', pos) - pos);
    const std::string where = fmt::format("{}:{}", pvd.string(), line_at(text, pos));
    const std::string file = xml_attribute(tag, "file"), time = xml_attribute(tag, "timestep");
    if (file.empty()) throw InputError(fmt::format("{}: <DataSet> without a file", where));
    out.push_back({time.empty() ? double(out.size()) : finite_number(time, where),
                   (pvd.parent_path() / file).string(), time_units});
  }
  if (out.empty()) throw InputError(fmt::format("{}: no <DataSet> entries", pvd.string()));
  std::stable_sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.time < b.time; });
  return out;
}

}  // namespace

std::vector<SeriesEntry> read_series(const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(path)) return read_pvd(path);
  std::vector<std::vector<SeriesEntry>> grids;
  std::string names;
  for (const auto& entry : fs::directory_iterator(path)) {
    if (entry.path().extension() != ".pvd") continue;
    auto series = read_pvd(entry.path());
    if (const auto ext = fs::path(series.front().file).extension(); ext != ".vti" && ext != ".pvti") continue;
    grids.push_back(std::move(series));
    names.append(" ").append(entry.path().filename().string());
  }
  if (grids.size() != 1)
    throw InputError(
        fmt::format("{}: {} .pvd series of image data (.vti, .pvti){}{}; expected one (name "
                    "the .pvd file instead of the folder)",
                    path, grids.size(), names.empty() ? "" : ":", names));
  return grids.front();
}

GridField read_grid_field(const std::string& path, const std::string& array) {
  const std::string text = read_whole_file(path);
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  GridField f;
  if (ext == ".csv" || ext == ".txt")
    f = read_csv(path, text);
  else if (ext == ".vtk")
    f = read_legacy_vtk(path, text, array);
  else if (ext == ".vti")
    f = read_vti(path, text, array);
  else if (ext == ".pvti")
    f = read_pvti(path, text, array);
  else
    throw InputError(
        fmt::format("{}: unknown field format '{}'; expected .csv, .txt, .vtk "
                    "(legacy ASCII STRUCTURED_POINTS), .vti (XML ImageData) or .pvti (its pieces)",
                    path, ext));
  if (f.void_count() == 0) f.is_void.clear();
  validate(f, path);
  return f;
}

}  // namespace shockfield::analysis
