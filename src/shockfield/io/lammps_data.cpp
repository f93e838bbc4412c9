#include "shockfield/io/lammps_data.hpp"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <unordered_map>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/line_reader.hpp"
#include "shockfield/geometry/shrink_wrap.hpp"

namespace shockfield::io {
namespace {

const char* const axis_name = "xyz";
constexpr long long kMinAtomRowBytes = 10;
// Far more types than any potential maps; bounds the per-type arrays sized from the header.
constexpr long long kMaxAtomTypes = 100000;

// Reader following the layout rules of LAMMPS read_data (docs of `read_data`).
class DataReader {
 public:
  DataReader(const std::filesystem::path& file, const std::array<geometry::Boundary, 3>& boundary)
      : r_(file) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    file_bytes_ = ec ? 0 : static_cast<long long>(size);
    out_.box.boundary = boundary;
  }

  DataFile read() {
    r_.require_next("the title line");  // the first line is always the title
    out_.title = r_.line();
    const bool more = header();
    for (bool in_section = more; in_section;) in_section = section();
    if (natoms_ > 0 && !have_atoms_)
      throw InputError(fmt::format("{}: the header declares {} atoms but there is no Atoms section",
                                   r_.name(), natoms_));
    return std::move(out_);
  }

 private:
  // Advances to the next line with content (comments stripped); false at the end of the file.
  bool next_content() {
    while (r_.next()) {
      const std::string& line = r_.line();
      const auto hash = line.find('#');
      text_ = line.substr(0, hash);
      comment_ = hash == std::string::npos ? "" : line.substr(hash + 1);
      words_ = split_words(text_);
      if (!words_.empty()) return true;
    }
    return false;
  }

  void require_content(const std::string& what) {
    if (!next_content())
      throw InputError(fmt::format("{}:{}: unexpected end of file, expected {}", r_.name(),
                                   r_.line_number() + 1, what));
  }

  std::string joined() const { return fmt::format("{}", fmt::join(words_, " ")); }

  // Header lines start with a number, section keywords with a word (LAMMPS read_data).
  bool starts_with_number() const {
    double v = 0;
    const std::string_view w = words_[0];
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    return ec == std::errc() && end == w.data() + w.size();
  }

  // Header lines until the first section keyword; false when the file ends in the header.
  bool header() {
    bool have_box[3] = {false, false, false};
    bool more = false;
    while ((more = next_content()) && starts_with_number()) header_line(have_box);
    check_header(have_box);
    return more;
  }

  void header_line(bool have_box[3]) {
    const auto& w = words_;
    if (w.size() == 2 && w[1] == "atoms") {
      natoms_ = r_.to_int(w[0], "the number of atoms");
      if (natoms_ < 0) r_.fail("expected a number of atoms >= 0");
    } else if (w.size() == 3 && w[1] == "atom" && w[2] == "types") {
      ntypes_ = r_.to_int(w[0], "the number of atom types");
      if (ntypes_ < 1 || ntypes_ > kMaxAtomTypes)
        r_.fail(fmt::format("expected a number of atom types in 1..{}, got {}", kMaxAtomTypes, ntypes_));
    } else if (w.size() == 4 && w[2].size() == 3 && w[2].substr(1) == "lo" && w[3].size() == 3 &&
               w[3].substr(1) == "hi" && w[2][0] == w[3][0] && w[2][0] >= 'x' && w[2][0] <= 'z') {
      const int d = w[2][0] - 'x';
      out_.box.lo[d] = r_.to_double(w[0], fmt::format("{}lo", w[2][0]));
      out_.box.hi[d] = r_.to_double(w[1], fmt::format("{}hi", w[2][0]));
      if (!(out_.box.lo[d] < out_.box.hi[d]) || !std::isfinite(out_.box.hi[d] - out_.box.lo[d]))
        r_.fail(fmt::format("expected {0}lo < {0}hi with a finite length, got {1} {2}", w[2][0],
                            out_.box.lo[d], out_.box.hi[d]));
      have_box[d] = true;
    } else if (w.size() == 6 && w[3] == "xy" && w[4] == "xz" && w[5] == "yz") {  // LAMMPS read_data
      static const char* names[3] = {"xy", "xz", "yz"};
      for (int k = 0; k < 3; ++k) {
        out_.box.tilt[k] = r_.to_double(w[k], names[k]);
        if (!std::isfinite(out_.box.tilt[k])) r_.fail(fmt::format("expected a finite tilt factor {}", names[k]));
      }
    } else if ((w.size() == 2 && (w[1] == "bonds" || w[1] == "angles" || w[1] == "dihedrals" || w[1] == "impropers")) ||
               (w.size() == 3 && w[2] == "types")) {
      if (r_.to_int(w[0], "a count") != 0)
        r_.fail(fmt::format("'{}': only atom style atomic is supported (no bonds, angles, dihedrals, impropers)", joined()));
    } else {
      r_.fail(fmt::format("unknown header line '{}' (expected 'N atoms', 'N atom types', "
                          "'lo hi xlo xhi' and the like, or a section keyword)", joined()));
    }
  }

  void check_header(const bool have_box[3]) {
    const auto missing = [&](const std::string& what) {
      throw InputError(fmt::format("{}:{}: the header has no '{}' line before the first section",
                                   r_.name(), r_.line_number(), what));
    };
    if (natoms_ < 0) missing("N atoms");
    if (ntypes_ < 0) missing("N atom types");
    for (int d = 0; d < 3; ++d)
      if (!have_box[d]) missing(fmt::format("{0}lo {0}hi", axis_name[d]));
    out_.box.check_tilt(fmt::format("{}: the 'xy xz yz' header line", r_.name()));
    out_.atoms.mass.assign(static_cast<std::size_t>(ntypes_), 0.0);
    out_.atoms.type_names.assign(static_cast<std::size_t>(ntypes_), "");
  }

  // The current line is a section keyword; reads its body. False when the file ends.
  bool section() {
    const std::string name = joined();
    if (name == "Masses") read_rows(ntypes_, "Masses", [&] { mass_row(); });
    else if (name == "Atoms") atoms_section();
    else if (name == "Velocities") {
      if (!have_atoms_) r_.fail("the Velocities section must come after the Atoms section");
      read_rows(natoms_, "Velocities", [&] { velocity_row(); });
      out_.has_velocities = true;
    } else if (name == "Pair Coeffs") read_rows(ntypes_, name, [] {});
    else if (name == "PairIJ Coeffs") read_rows(ntypes_ * (ntypes_ + 1) / 2, name, [] {});
    else r_.fail(fmt::format("unknown or unsupported section '{}' (expected Masses, Atoms or Velocities)", name));
    return next_content();
  }

  template <class Row>
  void read_rows(long long count, const std::string& section, Row row) {
    for (long long i = 0; i < count; ++i) {
      require_content(fmt::format("line {} of {} in the {} section", i + 1, count, section));
      row();
    }
  }

  int type_word(std::string_view w) const {
    const long long t = r_.to_int(w, "an atom type");
    if (t < 1 || t > ntypes_) r_.fail(fmt::format("atom type {} out of range 1..{}", t, ntypes_));
    return static_cast<int>(t);
  }

  void mass_row() {
    if (words_.size() != 2) r_.fail(fmt::format("expected 'type mass' in the Masses section, got {} words", words_.size()));
    const auto t = static_cast<std::size_t>(type_word(words_[0]) - 1);
    const double m = r_.to_double(words_[1], "a mass");
    if (!(m > 0)) r_.fail(fmt::format("expected a mass > 0, got {}", m));
    out_.atoms.mass[t] = m;
    const auto names = split_words(comment_);
    if (!names.empty()) out_.atoms.type_names[t] = std::string(names[0]);
  }

  void atoms_section() {
    const auto style = split_words(comment_);
    if (!style.empty() && style[0] != "atomic")
      r_.fail(fmt::format("atom style '{}' is not supported: expected 'Atoms # atomic'", style[0]));
    if (have_atoms_) r_.fail("second Atoms section");
    // Each atom needs a row of at least kMinAtomRowBytes ("1 1 0 0 0\n"): a larger count cannot
    // be in the file (refused before its rows are read).
    if (natoms_ > file_bytes_ / kMinAtomRowBytes)
      r_.fail(fmt::format("the header declares {} atoms, which cannot fit in a file of {} bytes",
                          natoms_, file_bytes_));
    have_atoms_ = true;
    read_rows(natoms_, "Atoms", [&] { atom_row(); });
  }

  void atom_row() {
    const auto& w = words_;
    if (w.size() != 5 && w.size() != 8)
      r_.fail(fmt::format("expected 5 values 'id type x y z' or 8 with image flags 'ix iy iz', got {}", w.size()));
    const long long id = r_.to_int(w[0], "an atom id");
    if (id < 1) r_.fail(fmt::format("expected an atom id >= 1, got {}", id));
    const int type = type_word(w[1]);
    Vec3 x;
    std::array<int, 3> image{0, 0, 0};
    for (int d = 0; d < 3; ++d) {
      x[d] = r_.to_double(w[2 + d], std::string(1, axis_name[d]));
      if (w.size() == 8) image[d] = image_flag(w[5 + d], d);
    }
    const geometry::Box& box = out_.box;
    const Vec3 margin = geometry::shrink_margin(box);  // LAMMPS grows shrink-wrapped dimensions by it first
    // A triclinic cell is bounded by its faces: compare fractional coordinates with [0, 1].
    const Vec3 s = box.triclinic() ? box.to_fractional(x) : x;
    const Vec3 lo = box.triclinic() ? Vec3::Zero() : box.lo, hi = box.triclinic() ? Vec3::Ones() : box.hi;
    for (int d = 0; d < 3; ++d) {
      const double pad = box.boundary[d] == geometry::Boundary::shrink ? margin[d] : 0.0;
      if (!box.periodic(d) && (s[d] < lo[d] - pad || s[d] > hi[d] + pad))
        r_.fail(fmt::format("atom {} at {} = {} is outside the non-periodic box {}lo {}hi = [{}, {}]{}",
                            id, axis_name[d], x[d], axis_name[d], axis_name[d], box.lo[d], box.hi[d],
                            pad > 0 ? fmt::format(" (shrink-wrapped: {} Å of margin on each side)", pad) : ""));
    }
    if (!box.try_wrap(x, image))
      r_.fail(fmt::format("atom {} at ({}, {}, {}) with image flags {} {} {} cannot be wrapped into the "
                          "periodic box: it is more than 2^31 box lengths away", id, x[0], x[1], x[2],
                          image[0], image[1], image[2]));
    if (!index_.emplace(id, out_.atoms.nlocal).second) r_.fail(fmt::format("duplicate atom id {}", id));
    out_.atoms.add(x, type - 1, id);
    out_.atoms.image.back() = image;
  }

  int image_flag(std::string_view w, int d) const {
    const long long n = r_.to_int(w, fmt::format("the image flag i{}", axis_name[d]));
    if (n < std::numeric_limits<int>::min() || n > std::numeric_limits<int>::max())
      r_.fail(fmt::format("image flag i{} = {} is outside the range of a 32-bit int", axis_name[d], n));
    return static_cast<int>(n);
  }

  void velocity_row() {
    if (words_.size() != 4) r_.fail(fmt::format("expected 4 values 'id vx vy vz' in the Velocities section, got {}", words_.size()));
    const long long id = r_.to_int(words_[0], "an atom id");
    const auto it = index_.find(id);
    if (it == index_.end()) r_.fail(fmt::format("velocity for atom id {} which is not in the Atoms section", id));
    for (int d = 0; d < 3; ++d)
      out_.atoms.v[it->second][d] = r_.to_double(words_[1 + d], fmt::format("v{}", axis_name[d]));
  }

  LineReader r_;
  DataFile out_;
  long long file_bytes_ = 0;
  long long natoms_ = -1, ntypes_ = -1;
  bool have_atoms_ = false;
  std::unordered_map<long long, std::size_t> index_;
  std::string text_, comment_;
  std::vector<std::string_view> words_;
};

}  // namespace

DataFile read_data(const std::filesystem::path& file, const std::array<geometry::Boundary, 3>& boundary) {
  return DataReader(file, boundary).read();
}

void write_data(const std::filesystem::path& file, const geometry::Box& box_in, const md::Atoms& atoms,
                const DataWriteOptions& options) {
  // LAMMPS write_data: pbc() then reset_box() on the owned atoms, before anything is written.
  geometry::Box box = box_in;
  std::vector<Vec3> x(atoms.x.begin(), atoms.x.begin() + static_cast<std::ptrdiff_t>(atoms.nlocal));
  std::vector<std::array<int, 3>> image(atoms.image.begin(), atoms.image.begin() + static_cast<std::ptrdiff_t>(atoms.nlocal));
  for (std::size_t i = 0; i < x.size(); ++i) box.wrap(x[i], image[i]);
  geometry::shrink_wrap(box, x, options.shrink_margin.value_or(geometry::shrink_margin(box_in)));
  fmt::memory_buffer buf;
  auto it = std::back_inserter(buf);
  // Layout of LAMMPS write_data (WriteData::header, atoms, velocities).
  fmt::format_to(it, "{}\n\n{} atoms\n{} atom types\n\n", options.title, atoms.nlocal, atoms.ntypes());
  for (int d = 0; d < 3; ++d)
    fmt::format_to(it, "{} {} {}lo {}hi\n", box.lo[d], box.hi[d], axis_name[d], axis_name[d]);
  if (box.triclinic()) fmt::format_to(it, "{} {} {} xy xz yz\n", box.tilt[0], box.tilt[1], box.tilt[2]);
  fmt::format_to(it, "\nMasses\n\n");
  for (int t = 0; t < atoms.ntypes(); ++t) {
    const auto ut = static_cast<std::size_t>(t);
    const bool named = ut < atoms.type_names.size() && !atoms.type_names[ut].empty();
    fmt::format_to(it, "{} {}{}\n", t + 1, atoms.mass[ut], named ? " # " + atoms.type_names[ut] : "");
  }
  fmt::format_to(it, "\nAtoms # atomic\n\n");
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    fmt::format_to(it, "{} {} {} {} {}", atoms.id[i], atoms.type[i] + 1, x[i].x(), x[i].y(), x[i].z());
    if (options.image_flags) fmt::format_to(it, " {} {} {}", image[i][0], image[i][1], image[i][2]);
    buf.push_back('\n');
  }
  if (options.velocities) {
    fmt::format_to(it, "\nVelocities\n\n");
    for (std::size_t i = 0; i < atoms.nlocal; ++i)
      fmt::format_to(it, "{} {} {} {}\n", atoms.id[i], atoms.v[i].x(), atoms.v[i].y(), atoms.v[i].z());
  }
  replace_file(file, {buf.data(), buf.size()});
}

}  // namespace shockfield::io
