#include "shockfield/io/lammps_dump.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <limits>
#include <set>

#include "shockfield/core/error.hpp"
#include "shockfield/io/line_reader.hpp"

namespace shockfield::io {

std::string DumpFrame::where() const {
  return fmt::format("{}{}dump frame of timestep {}", source, source.empty() ? "" : ": ", timestep);
}

std::optional<std::size_t> DumpFrame::find(std::string_view name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(it - columns.begin());
}

const std::vector<double>& DumpFrame::column(std::string_view name) const {
  const auto c = find(name);
  if (!c) throw InputError(fmt::format("{} has no column '{}' (columns: {})",
                                       where(), name, fmt::join(columns, " ")));
  return values[*c];
}

void DumpFrame::set_column(const std::string& name, std::vector<double> data) {
  if (!values.empty() && data.size() != natoms())
    throw InputError(fmt::format("dump column '{}' has {} values, the frame has {} atoms", name,
                                 data.size(), natoms()));
  if (const auto c = find(name)) {
    values[*c] = std::move(data);
    return;
  }
  columns.push_back(name);
  values.push_back(std::move(data));
}

namespace {
// The values of an integer column as integers; InputError for a value that is not a whole number
// in [lo, hi] (a converted 1e300 would overflow the integer).
template <class Int>
std::vector<Int> whole_numbers(const DumpFrame& frame, std::string_view name, double lo, double hi) {
  const auto& c = frame.column(name);
  std::vector<Int> out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!(c[i] >= lo && c[i] <= hi) || c[i] != std::floor(c[i]))
      throw InputError(fmt::format("{}: row {} has {} = {}; expected a whole "
                                   "number in [{}, {}]", frame.where(), i + 1, name, c[i], lo, hi));
    out[i] = static_cast<Int>(c[i]);
  }
  return out;
}
}  // namespace

std::vector<std::int64_t> DumpFrame::ids() const {
  return whole_numbers<std::int64_t>(*this, "id", 0, 9.0e18);  // < 2^63
}

std::vector<int> DumpFrame::types() const {
  return whole_numbers<int>(*this, "type", 1, std::numeric_limits<int>::max());
}

std::vector<Vec3> DumpFrame::positions() const {
  // The position columns LAMMPS `dump custom` can write, in order of preference.
  static const std::array<std::array<const char*, 3>, 3> sets{
      {{"x", "y", "z"}, {"xu", "yu", "zu"}, {"xs", "ys", "zs"}}};
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const auto& names = sets[s];
    if (!has(names[0]) || !has(names[1]) || !has(names[2])) continue;
    std::vector<Vec3> out(natoms());
    for (int d = 0; d < 3; ++d) {
      const auto& c = column(names[d]);
      for (std::size_t i = 0; i < c.size(); ++i) out[i][d] = c[i];
    }
    if (s == 2)  // scaled: x = lo + h s
      for (auto& x : out) x = box.from_fractional(x);
    return out;
  }
  throw InputError(fmt::format("{} has no positions (x y z, xu yu zu or "
                               "xs ys zs); columns: {}", where(), fmt::join(columns, " ")));
}

bool is_integer_column(std::string_view name) {
  // Written with "%d" by LAMMPS DumpCustom.
  static const std::set<std::string_view> names{"id", "type", "mol", "proc", "procp1", "ix", "iy", "iz"};
  return names.count(name) > 0;
}

std::string dump_bounds_code(geometry::Boundary b) {
  const char c = geometry::boundary_code(b);
  return {c, c};
}

namespace {

// The value of one LAMMPS `dump custom` per-atom attribute for atom i.
std::function<double(std::size_t)> atom_field(const std::string& field, const geometry::Box& box,
                                              const md::Atoms& atoms) {
  if (field == "id") return [&](std::size_t i) { return static_cast<double>(atoms.id[i]); };
  if (field == "type" || field == "element") return [&](std::size_t i) { return atoms.type[i] + 1.0; };
  if (field == "mass") return [&](std::size_t i) { return atoms.mass_of(i); };
  const auto axis = [](char c) { return c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1; };
  if (field.size() == 1 && axis(field[0]) >= 0)  // x y z
    return [&, d = axis(field[0])](std::size_t i) { return atoms.x[i][d]; };
  if (field.size() == 2 && field[1] == 'u' && axis(field[0]) >= 0)  // xu yu zu: unwrapped
    return [&, d = axis(field[0])](std::size_t i) { return atoms.x[i][d] + box.lattice_shift(atoms.image[i])[d]; };
  if (field.size() == 2 && axis(field[1]) >= 0) {
    const int d = axis(field[1]);
    if (field[0] == 'i') return [&, d](std::size_t i) { return double(atoms.image[i][d]); };
    if (field[0] == 'v') return [&, d](std::size_t i) { return atoms.v[i][d]; };
    if (field[0] == 'f') return [&, d](std::size_t i) { return atoms.f[i][d]; };
  }
  throw InputError(fmt::format("dump field '{}' is not one of id type element x y z xu yu zu ix iy iz vx "
                               "vy vz fx fy fz mass", field));
}

}  // namespace

DumpFrame make_dump_frame(long long timestep, const geometry::Box& box, const md::Atoms& atoms,
                          const std::vector<std::string>& fields) {
  DumpFrame frame;
  frame.timestep = timestep;
  frame.box = box;
  for (int d = 0; d < 3; ++d) frame.bounds[d] = dump_bounds_code(box.boundary[d]);
  if (std::find(fields.begin(), fields.end(), "element") != fields.end()) {
    for (int t = 0; t < atoms.ntypes(); ++t)
      if (static_cast<std::size_t>(t) >= atoms.type_names.size() || atoms.type_names[t].empty())
        throw InputError(fmt::format("dump field 'element' needs an element name for every atom type; "
                                     "type {} has none", t + 1));
    frame.element_names = atoms.type_names;
  }
  for (const std::string& field : fields) {
    const auto value = atom_field(field, box, atoms);
    std::vector<double> data(atoms.nlocal);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = value(i);
    frame.set_column(field, std::move(data));
  }
  return frame;
}

namespace {

// Reduces a two-letter dump bounds code to one Box boundary (see DumpFrame::bounds).
geometry::Boundary boundary_from_code(const LineReader& r, std::string_view code) {
  const auto valid = [](char c) { return c == 'p' || c == 'f' || c == 's' || c == 'm'; };
  if (code.size() != 2 || !valid(code[0]) || !valid(code[1]) || ((code[0] == 'p') != (code[1] == 'p')))
    r.fail(fmt::format("expected a boundary code of two letters from p, f, s, m (pp, ff, fs, mm, ...), got '{}'", code));
  if (code[0] == 'p') return geometry::Boundary::periodic;
  if (code == "ff") return geometry::Boundary::fixed;
  return geometry::Boundary::shrink;
}

void read_box(LineReader& r, DumpFrame& frame) {
  const auto words = r.words();  // ITEM: BOX BOUNDS [xy xz yz] [codes...]
  std::vector<std::string> codes(words.begin() + 3, words.end());
  const bool triclinic = !codes.empty() && codes.front() == "xy";
  if (triclinic) {
    if (codes.size() < 3 || codes[1] != "xz" || codes[2] != "yz")
      r.fail(fmt::format("expected 'xy xz yz' after BOX BOUNDS of a triclinic box, got '{}'", r.line()));
    codes.erase(codes.begin(), codes.begin() + 3);
  }
  if (!codes.empty() && codes.size() != 3)
    r.fail(fmt::format("expected three boundary codes after BOX BOUNDS (e.g. 'pp pp ff'), got {}", codes.size()));
  for (std::size_t d = 0; d < codes.size(); ++d) {
    frame.bounds[d] = codes[d];
    frame.box.boundary[d] = boundary_from_code(r, codes[d]);
  }
  // A triclinic box gives its bounding box, each line with one tilt factor (LAMMPS's convention,
  // https://docs.lammps.org/Howto_triclinic.html: "xlo_bound xhi_bound xy" and so on).
  static const char* axis = "xyz";
  static const char* tilt_name[3] = {"xy", "xz", "yz"};
  Vec3 lo, hi, tilt = Vec3::Zero();
  for (int d = 0; d < 3; ++d) {
    const std::string line = triclinic ? fmt::format("{0}lo_bound {0}hi_bound {1}", axis[d], tilt_name[d])
                                       : fmt::format("{0}lo {0}hi", axis[d]);
    r.require_next(fmt::format("the {} line of BOX BOUNDS", line));
    const auto w = r.words();
    const std::size_t expected = triclinic ? 3 : 2;
    if (w.size() != expected)
      r.fail(fmt::format("expected {} numbers '{}', got {} words", expected, line, w.size()));
    lo[d] = r.to_double(w[0], fmt::format("{}lo", axis[d]));
    hi[d] = r.to_double(w[1], fmt::format("{}hi", axis[d]));
    if (triclinic) tilt[d] = r.to_double(w[2], tilt_name[d]);
    if (!(lo[d] < hi[d])) r.fail(fmt::format("expected {0}lo < {0}hi, got {1} {2}", axis[d], lo[d], hi[d]));
  }
  frame.box = geometry::box_from_bounds(lo, hi, tilt, frame.box.boundary);
  for (int d = 0; d < 3; ++d)
    if (!(frame.box.lo[d] < frame.box.hi[d]))
      r.fail(fmt::format("the tilt factors ({}) leave no room in the {} bounds {} {} of the box", fmt::join(tilt, " "),
                         axis[d], lo[d], hi[d]));
  try {
    frame.box.check_tilt("BOX BOUNDS");
  } catch (const InputError& e) {
    r.fail(e.what());
  }
}

// The single word on the line after an ITEM header.
std::string value_line(LineReader& r, const std::string& what) {
  r.require_next(what);
  const auto w = r.words();
  if (w.size() != 1) r.fail(fmt::format("expected {} alone on the line, got '{}'", what, r.line()));
  return std::string(w[0]);
}

// The 1-based index of an element name in frame.element_names, added when new.
double element_index(DumpFrame& frame, std::string_view name) {
  auto& names = frame.element_names;
  const auto k = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  if (k == names.size()) names.emplace_back(name);
  return static_cast<double>(k + 1);
}

void read_atoms(LineReader& r, DumpFrame& frame, long long natoms) {
  const auto words = r.words();  // ITEM: ATOMS col...
  std::set<std::string_view> seen;
  for (std::size_t i = 2; i < words.size(); ++i) {
    if (!seen.insert(words[i]).second) r.fail(fmt::format("column '{}' appears twice in ITEM: ATOMS", words[i]));
    frame.columns.emplace_back(words[i]);
  }
  if (frame.columns.empty()) r.fail("expected column names after ITEM: ATOMS (e.g. 'id type x y z')");
  const std::size_t ncols = frame.columns.size();
  const auto element = frame.find("element");
  // Rows are appended as they are read, never sized from the count: a count larger than the
  // file ends in "unexpected end of file", not in an allocation failure.
  frame.values.assign(ncols, {});
  for (long long i = 0; i < natoms; ++i) {
    r.require_next(fmt::format("atom row {} of {} at timestep {}", i + 1, natoms, frame.timestep));
    const auto w = r.words();
    if (w.size() != ncols)
      r.fail(fmt::format("expected {} values ({}), got {}", ncols, fmt::join(frame.columns, " "), w.size()));
    for (std::size_t c = 0; c < ncols; ++c)
      frame.values[c].push_back(c == element ? element_index(frame, w[c])
                                             : r.to_double(w[c], "column '" + frame.columns[c] + "'"));
  }
}

}  // namespace

std::vector<DumpFrame> read_dump(std::istream& in, const std::string& name) {
  LineReader r(in, name);
  std::vector<DumpFrame> frames;
  DumpFrame frame;
  bool have_step = false, have_box = false;
  long long natoms = -1;
  while (r.next()) {
    const std::string& line = r.line();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.rfind("ITEM:", 0) != 0) r.fail(fmt::format("expected an 'ITEM:' line, got '{}'", line));
    const auto words = r.words();
    if (words.size() >= 2 && words[1] == "TIMESTEP") {
      frame.timestep = r.to_int(value_line(r, "the timestep"), "the timestep");
      have_step = true;
    } else if (words.size() >= 2 && words[1] == "TIME") {
      frame.time = r.to_double(value_line(r, "the time"), "the time");
    } else if (words.size() >= 2 && words[1] == "UNITS") {
      frame.units = value_line(r, "the unit style");
    } else if (words.size() >= 4 && words[1] == "NUMBER" && words[2] == "OF" && words[3] == "ATOMS") {
      natoms = r.to_int(value_line(r, "the number of atoms"), "the number of atoms");
      if (natoms < 0) r.fail("expected a number of atoms >= 0");
    } else if (words.size() >= 3 && words[1] == "BOX" && words[2] == "BOUNDS") {
      read_box(r, frame);
      have_box = true;
    } else if (words.size() >= 2 && words[1] == "ATOMS") {
      if (!have_step || natoms < 0 || !have_box)
        r.fail("ITEM: ATOMS before the frame's ITEM: TIMESTEP, NUMBER OF ATOMS and BOX BOUNDS");
      read_atoms(r, frame, natoms);
      frame.source = name;
      frames.push_back(std::move(frame));
      frame = DumpFrame{};
      have_step = have_box = false;
      natoms = -1;
    } else {
      r.fail(fmt::format("unknown section '{}' (expected TIMESTEP, TIME, UNITS, NUMBER OF ATOMS, "
                         "BOX BOUNDS or ATOMS)", line));
    }
  }
  if (have_step || have_box || natoms >= 0)
    throw InputError(fmt::format("{}:{}: unexpected end of file, expected ITEM: ATOMS of timestep {}",
                                 name, r.line_number() + 1, frame.timestep));
  if (frames.empty()) throw InputError(fmt::format("{}: no dump frame found (empty file?)", name));
  return frames;
}

std::vector<DumpFrame> read_dump(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open dump file for reading", file.string()));
  return read_dump(in, file.string());
}

void write_dump_frame(std::ostream& out, const DumpFrame& frame, const DumpWriteOptions& options) {
  const std::size_t n = frame.natoms();
  if (frame.columns.size() != frame.values.size())
    throw InputError(fmt::format("dump frame: {} column names for {} value arrays",
                                 frame.columns.size(), frame.values.size()));
  for (std::size_t c = 0; c < frame.values.size(); ++c)
    if (frame.values[c].size() != n)
      throw InputError(fmt::format("dump frame: column '{}' has {} values, column '{}' has {}",
                                   frame.columns[c], frame.values[c].size(), frame.columns[0], n));
  std::vector<bool> is_int(frame.columns.size());
  for (std::size_t c = 0; c < is_int.size(); ++c) is_int[c] = is_integer_column(frame.columns[c]);
  const auto element = frame.find("element");
  const auto element_name = [&](double k) -> const std::string& {
    if (!(k >= 1 && k <= static_cast<double>(frame.element_names.size())))
      throw InputError(fmt::format("dump frame: element index {} has no name ({} names)", k, frame.element_names.size()));
    return frame.element_names[static_cast<std::size_t>(k) - 1];
  };

  fmt::memory_buffer buf;
  auto it = std::back_inserter(buf);
  // Header as written by LAMMPS DumpCustom::header_item (units and time first, when present).
  if (!frame.units.empty()) fmt::format_to(it, "ITEM: UNITS\n{}\n", frame.units);
  if (frame.time) fmt::format_to(it, "ITEM: TIME\n{}\n", *frame.time);
  fmt::format_to(it, "ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\n", frame.timestep, n);
  const geometry::Box& box = frame.box;
  if (box.triclinic()) {  // LAMMPS DumpCustom::header_item_triclinic
    fmt::format_to(it, "ITEM: BOX BOUNDS xy xz yz {} {} {}\n", frame.bounds[0], frame.bounds[1], frame.bounds[2]);
    const Vec3 lo = box.bound_lo(), hi = box.bound_hi();
    for (int d = 0; d < 3; ++d) fmt::format_to(it, "{:.16e} {:.16e} {:.16e}\n", lo[d], hi[d], box.tilt[d]);
  } else {
    fmt::format_to(it, "ITEM: BOX BOUNDS {} {} {}\n", frame.bounds[0], frame.bounds[1], frame.bounds[2]);
    for (int d = 0; d < 3; ++d) fmt::format_to(it, "{:.16e} {:.16e}\n", box.lo[d], box.hi[d]);
  }
  fmt::format_to(it, "ITEM: ATOMS {}\n", fmt::join(frame.columns, " "));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < frame.values.size(); ++c) {
      if (c) buf.push_back(' ');
      const double v = frame.values[c][i];
      if (c == element) fmt::format_to(it, "{}", element_name(v));
      else if (is_int[c]) fmt::format_to(it, "{}", std::llround(v));
      else if (options.full_precision) fmt::format_to(it, "{}", v);
      else fmt::format_to(it, "{:g}", v);
    }
    buf.push_back('\n');
    if (buf.size() > (1u << 20)) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

DumpWriter::DumpWriter(const std::filesystem::path& file, DumpWriteOptions options)
    : file_(file), out_(file), options_(options) {}

void DumpWriter::write(const DumpFrame& frame) {
  write_dump_frame(out_.stream(), frame, options_);
  out_.flush();
}

}  // namespace shockfield::io
