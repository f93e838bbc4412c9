// Extended XYZ reader (io/extxyz.hpp): frames of ASE and OVITO files as dump frames, validated as
// strictly as the LAMMPS dump reader (every error names the file and the line).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>

#include "shockfield/core/error.hpp"
#include "shockfield/io/extxyz.hpp"
#include "shockfield/io/line_reader.hpp"

namespace shockfield::io {
namespace {

// key=value pairs of the comment line; values may be "quoted" or {braced}; a key alone is "T".
std::vector<std::pair<std::string, std::string>> comment_pairs(const LineReader& r) {
  const std::string& s = r.line();
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t i = 0;
  const auto space = [&](std::size_t k) { return std::isspace(static_cast<unsigned char>(s[k])) != 0; };
  while (true) {
    while (i < s.size() && space(i)) ++i;
    if (i >= s.size()) return out;
    const std::size_t start = i;
    while (i < s.size() && !space(i) && s[i] != '=') ++i;
    std::string key = s.substr(start, i - start);
    std::size_t j = i;
    while (j < s.size() && space(j)) ++j;
    if (j >= s.size() || s[j] != '=') {
      out.emplace_back(std::move(key), "T");
      continue;
    }
    i = j + 1;
    while (i < s.size() && space(i)) ++i;
    std::string value;
    if (i < s.size() && (s[i] == '"' || s[i] == '{')) {
      const char close = s[i] == '"' ? '"' : '}';
      const std::size_t end = s.find(close, i + 1);
      if (end == std::string::npos) r.fail(fmt::format("the value of {} opens with {} but never closes", key, s[i]));
      value = s.substr(i + 1, end - i - 1);
      i = end + 1;
    } else {
      const std::size_t begin = i;
      while (i < s.size() && !space(i)) ++i;
      value = s.substr(begin, i - begin);
    }
    if (key.empty()) r.fail("a value without a key (=... with nothing before it) on the comment line");
    out.emplace_back(std::move(key), std::move(value));
  }
}

bool same_key(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// One column of the atom rows: which frame column it fills (empty: left out) and how to read it.
struct RowColumn {
  std::string name;
  char kind = 'R';  // R real, I integer, L logical, S string
};

// The atom-row columns of Properties=name:type:count:...
std::vector<RowColumn> property_columns(const LineReader& r, const std::string& spec) {
  std::vector<std::string> parts;
  for (std::size_t begin = 0;;) {
    const std::size_t end = spec.find(':', begin);
    parts.push_back(spec.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  if (parts.size() % 3 != 0)
    r.fail(fmt::format("Properties=\"{}\": expected name:type:count triples (e.g. species:S:1:pos:R:3)", spec));
  std::vector<RowColumn> cols;
  std::set<std::string> seen;
  for (std::size_t p = 0; p < parts.size(); p += 3) {
    const std::string& name = parts[p];
    const std::string& type = parts[p + 1];
    if (name.empty() || type.size() != 1 || std::string("RILS").find(type[0]) == std::string::npos)
      r.fail(fmt::format("Properties: property '{}' has type '{}'; expected R, I, L or S", name, type));
    if (!seen.insert(name).second) r.fail(fmt::format("Properties: property '{}' appears twice", name));
    const long long count = r.to_int(parts[p + 2], fmt::format("the column count of property '{}'", name));
    if (count < 1 || count > 64) r.fail(fmt::format("Properties: property '{}' has {} columns; expected 1 to 64", name, count));
    const char kind = type[0];
    static const char* xyz[3] = {"x", "y", "z"};
    const bool triple = count == 3 && kind == 'R';
    for (long long k = 0; k < count; ++k) {
      std::string column;
      if (name == "species" && count == 1 && kind == 'S') column = "species";
      else if (kind == 'S') column = "";  // another string property: left out
      else if (triple && name == "pos") column = xyz[k];
      else if (triple && (name == "velo" || name == "velocities")) column = std::string("v") + xyz[k];
      else if (triple && name == "forces") column = std::string("f") + xyz[k];
      else if (count == 1) column = name;
      else column = fmt::format("{}[{}]", name, k + 1);
      if (name == "id" && !(count == 1 && kind == 'I')) r.fail("Properties: id must be id:I:1");
      if ((name == "pos" || name == "species") && !(kind == (name == "pos" ? 'R' : 'S') && count == (name == "pos" ? 3 : 1)))
        r.fail(fmt::format("Properties: expected {}, got {}:{}:{}", name == "pos" ? "pos:R:3" : "species:S:1", name, type, count));
      cols.push_back({column, kind});
    }
  }
  if (!seen.count("pos")) r.fail(fmt::format("Properties=\"{}\" has no pos:R:3 (the positions)", spec));
  return cols;
}

// Numbers of a quoted list ("a b c ..."), exactly `count` of them.
std::vector<double> numbers(const LineReader& r, const std::string& key, const std::string& value, std::size_t count) {
  const auto words = split_words(value);
  if (words.size() != count)
    r.fail(fmt::format("{}=\"{}\": expected {} numbers, got {}", key, value, count, words.size()));
  std::vector<double> out;
  for (const auto& w : words) out.push_back(r.to_double(w, key + " value"));
  return out;
}

struct PendingFrame {
  DumpFrame frame;
  std::vector<std::string> species;
  bool has_lattice = false;
  int count_line = 0;  ///< line of the frame's atom count
};

// The comment line: box, boundaries, timestep, time and the row columns.
std::vector<RowColumn> read_comment(const LineReader& r, PendingFrame& p, long long index) {
  DumpFrame& f = p.frame;
  f.timestep = index;
  std::string properties = "species:S:1:pos:R:3", pbc;
  std::vector<double> lattice, origin{0, 0, 0};
  for (const auto& [key, value] : comment_pairs(r)) {
    if (same_key(key, "Lattice")) lattice = numbers(r, "Lattice", value, 9);
    else if (same_key(key, "Origin")) origin = numbers(r, "Origin", value, 3);
    else if (same_key(key, "Properties")) properties = value;
    else if (same_key(key, "pbc")) pbc = value;
    else if (same_key(key, "Timestep")) f.timestep = r.to_int(value, "Timestep (an integer)");
    else if (same_key(key, "Time")) f.time = r.to_double(value, "Time");
  }
  p.has_lattice = !lattice.empty();
  std::array<bool, 3> periodic{p.has_lattice, p.has_lattice, p.has_lattice};
  if (!pbc.empty()) {
    const auto w = split_words(pbc);
    if (w.size() != 3) r.fail(fmt::format("pbc=\"{}\": expected three of T and F (e.g. \"T T F\")", pbc));
    for (int d = 0; d < 3; ++d) {
      if (w[d] != "T" && w[d] != "F" && w[d] != "True" && w[d] != "False")
        r.fail(fmt::format("pbc=\"{}\": expected three of T and F (e.g. \"T T F\")", pbc));
      periodic[d] = w[d][0] == 'T';
    }
  }
  if (!p.has_lattice && (periodic[0] || periodic[1] || periodic[2]))
    r.fail("pbc has a periodic axis but the comment line has no Lattice (the periodic box)");
  if (p.has_lattice) {
    // LAMMPS's restricted triclinic cell: a = (lx, 0, 0), b = (xy, ly, 0), c = (xz, yz, lz).
    double scale = 0;
    for (double v : lattice) scale = std::max(scale, std::abs(v));
    const auto component = [&](int vector, int d) { return lattice[static_cast<std::size_t>(3 * vector + d)]; };
    if (std::abs(component(0, 1)) > 1e-12 * scale || std::abs(component(0, 2)) > 1e-12 * scale ||
        std::abs(component(1, 2)) > 1e-12 * scale)
      r.fail(fmt::format("Lattice=\"{}\" is a general triclinic cell: shockfield (as LAMMPS) needs the restricted "
                         "form, the first cell vector along x and the second in the xy plane (ay = az = bz = 0); "
                         "rotate the cell and the atoms first", fmt::join(lattice, " ")));
    for (int d = 0; d < 3; ++d) {
      const double length = component(d, d);
      if (!(length > 0))
        r.fail(fmt::format("Lattice: cell vector {} has length {} along {}; expected > 0", d + 1, length, "xyz"[d]));
      f.box.lo[d] = origin[static_cast<std::size_t>(d)];
      f.box.hi[d] = origin[static_cast<std::size_t>(d)] + length;
      if (!(f.box.hi[d] > f.box.lo[d]) || !std::isfinite(f.box.hi[d]))
        r.fail(fmt::format("Lattice and Origin: the box along {} is too small for its position ({} + {})", "xyz"[d],
                           f.box.lo[d], length));
    }
    // Off-diagonal entries below the round-off floor are zero: the box stays orthogonal.
    const auto tilt = [&](int vector, int d) {
      const double v = component(vector, d);
      return std::abs(v) > 1e-12 * scale ? v : 0.0;
    };
    f.box.tilt = Vec3(tilt(1, 0), tilt(2, 0), tilt(2, 1));
  }
  for (int d = 0; d < 3; ++d) {
    f.box.boundary[d] = periodic[static_cast<std::size_t>(d)] ? geometry::Boundary::periodic : geometry::Boundary::shrink;
    f.bounds[static_cast<std::size_t>(d)] = periodic[static_cast<std::size_t>(d)] ? "pp" : "ss";
  }
  try {
    f.box.check_tilt("Lattice");
  } catch (const InputError& e) {
    r.fail(e.what());
  }
  return property_columns(r, properties);
}

// The atom rows of a frame.
void read_rows(LineReader& r, PendingFrame& p, const std::vector<RowColumn>& cols, long long natoms) {
  DumpFrame& f = p.frame;
  std::vector<int> slot(cols.size(), -1);  // frame column of each row column
  for (std::size_t c = 0; c < cols.size(); ++c)
    if (!cols[c].name.empty() && cols[c].name != "species") {
      f.columns.push_back(cols[c].name);
      slot[c] = static_cast<int>(f.columns.size() - 1);
    }
  f.values.assign(f.columns.size(), {});
  for (long long i = 0; i < natoms; ++i) {
    r.require_next(fmt::format("atom row {} of {} (frame of timestep {})", i + 1, natoms, f.timestep));
    const auto w = r.words();
    if (w.size() != cols.size())
      r.fail(fmt::format("expected {} values per atom row (Properties), got {}", cols.size(), w.size()));
    for (std::size_t c = 0; c < cols.size(); ++c) {
      if (cols[c].name == "species") p.species.emplace_back(w[c]);
      if (slot[c] < 0) continue;
      double v = 0;
      const std::string what = fmt::format("property column '{}'", cols[c].name);
      if (cols[c].kind == 'L') {
        if (w[c] != "T" && w[c] != "F" && w[c] != "True" && w[c] != "False")
          r.fail(fmt::format("expected {} (T or F), got '{}'", what, w[c]));
        v = w[c][0] == 'T' ? 1 : 0;
      } else if (cols[c].kind == 'I') {
        v = static_cast<double>(r.to_int(w[c], what));
      } else {
        v = r.to_double(w[c], what);
      }
      f.values[static_cast<std::size_t>(slot[c])].push_back(v);
    }
  }
}

bool positive_integer(const std::string& s) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && v >= 1 && v <= 1000000;
}

// Species → type (and element) columns, over the whole file; ids in file order when absent;
// shrink-wrapped axes around the atoms.
void finish(std::vector<PendingFrame>& pending, const std::string& name) {
  bool numeric = true;
  std::vector<std::string> names;
  for (const auto& p : pending)
    for (const auto& s : p.species) {
      numeric = numeric && positive_integer(s);
      if (std::find(names.begin(), names.end(), s) == names.end()) names.push_back(s);
    }
  for (auto& p : pending) {
    DumpFrame& f = p.frame;
    const std::size_t n = f.natoms();
    f.source = name;
    std::vector<double> type(p.species.size()), id(n);
    for (std::size_t i = 0; i < p.species.size(); ++i)
      type[i] = numeric ? std::stod(p.species[i])
                        : double(std::find(names.begin(), names.end(), p.species[i]) - names.begin() + 1);
    for (std::size_t i = 0; i < n; ++i) id[i] = double(i + 1);
    std::vector<std::string> columns = std::move(f.columns);
    std::vector<std::vector<double>> values = std::move(f.values);
    f.columns.clear();
    f.values.clear();
    const bool has_id = std::find(columns.begin(), columns.end(), "id") != columns.end();
    if (!has_id) f.set_column("id", std::move(id));
    if (!p.species.empty() || n == 0) f.set_column("type", type);
    if (!numeric && (!p.species.empty() || n == 0)) {
      f.element_names = names;
      f.set_column("element", std::move(type));
    }
    for (std::size_t c = 0; c < columns.size(); ++c) f.set_column(columns[c], std::move(values[c]));
    if (n == 0) continue;
    const std::vector<Vec3> x = f.positions();
    for (int d = 0; d < 3; ++d) {
      if (f.box.boundary[d] != geometry::Boundary::shrink || p.has_lattice) continue;
      double lo = x[0][d], hi = x[0][d];
      for (const Vec3& v : x) lo = std::min(lo, v[d]), hi = std::max(hi, v[d]);
      if (hi - lo < 1.0) lo -= 0.5, hi += 0.5;  // atoms in one plane: a 1 Å slab around them
      f.box.lo[d] = lo;
      f.box.hi[d] = hi;
    }
  }
}

}  // namespace

std::vector<DumpFrame> read_extxyz(std::istream& in, const std::string& name, std::vector<int>* count_lines) {
  LineReader r(in, name);
  std::vector<PendingFrame> pending;
  while (r.next()) {
    if (r.line().find_first_not_of(" \t") == std::string::npos) continue;  // blank lines between frames
    const auto w = r.words();
    if (w.size() != 1) r.fail(fmt::format("expected the number of atoms of a frame alone on the line, got '{}'", r.line()));
    const long long natoms = r.to_int(w[0], "the number of atoms of a frame");
    if (natoms < 0) r.fail(fmt::format("expected a number of atoms >= 0, got {}", natoms));
    PendingFrame p;
    p.count_line = r.line_number();
    r.require_next(fmt::format("the comment line of frame {} (Lattice=..., Properties=...)", pending.size() + 1));
    const std::vector<RowColumn> cols = read_comment(r, p, static_cast<long long>(pending.size()));
    read_rows(r, p, cols, natoms);
    pending.push_back(std::move(p));
  }
  if (pending.empty()) throw InputError(fmt::format("{}: no extended XYZ frame found (empty file?)", name));
  finish(pending, name);
  std::vector<DumpFrame> frames;
  for (auto& p : pending) {
    frames.push_back(std::move(p.frame));
    if (count_lines) count_lines->push_back(p.count_line);
  }
  return frames;
}

std::vector<DumpFrame> read_extxyz(const std::filesystem::path& file, std::vector<int>* count_lines) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open extended XYZ file for reading", file.string()));
  return read_extxyz(in, file.string(), count_lines);
}

}  // namespace shockfield::io
