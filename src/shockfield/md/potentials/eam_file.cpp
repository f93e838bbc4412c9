#include "shockfield/md/potentials/eam_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"

namespace shockfield::md::potentials {
namespace {

// The smallest table length the 4-point interpolation and the spline accept without reading
// outside the table (pair_eam.cpp file2array() uses entries k-1..k+2 with 2 <= k <= n-2).
constexpr int kMinTableLength = 5;
// Each tabulated value takes at least two bytes (a digit and a separator): a longer table cannot
// be in the file, and is refused before anything is sized by it.
constexpr std::uintmax_t kMinValueBytes = 2;
// Sane bounds: EAM cutoffs are a few Å (the longest in LAMMPS's potentials folder is 10.1 Å);
// atomic masses lie between hydrogen's 1.008 and about 300 amu.
constexpr double kMaxCutoff = 100.0;
constexpr double kMinMass = 1e-3, kMaxMass = 1e4;
// The finest table spacing (drho, and dr in Å) a file may give. The splines' slopes (the forces)
// are differences of tabulated values, each rounded at ~1e-16 relative, divided by the spacing:
// below 1e-10 that rounding alone is amplified by more than 1e10, and ρ or r / spacing no longer
// fits the tables (drho = 1e-300 put every density beyond the last row). LAMMPS's files use
// spacings of 1e-4 to 2e-2, six orders of magnitude above.
constexpr double kMinSpacing = 1e-10;

std::vector<std::string> split(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// Line records of a potential file with LAMMPS TextFileReader semantics (see the header).
class Records {
 public:
  explicit Records(const std::filesystem::path& file) : name_(file.string()), in_(file) {
    if (!in_) throw InputError(fmt::format("{}: cannot open EAM potential file", name_));
    std::error_code ec;
    bytes_ = std::filesystem::file_size(file, ec);
    if (ec) bytes_ = 0;
  }

  /// The most values a table of this file can hold.
  std::uintmax_t max_values() const { return bytes_ / kMinValueBytes; }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(fmt::format("{}:{}: {}", name_, line_number_, message));
  }

  // A comment or title line (read whole, '#' included).
  void skip_line(const std::string& what) {
    std::string line;
    if (!std::getline(in_, line)) fail(fmt::format("unexpected end of file, expected {}", what));
    ++line_number_;
  }

  // Reads lines (comments stripped) until at least n words are collected; returns all of them.
  std::vector<std::string> words(std::size_t n, const std::string& what) {
    std::vector<std::string> out;
    while (out.empty() || out.size() < n) {
      std::string line;
      if (!next_data_line(line)) fail(fmt::format("unexpected end of file, expected {}", what));
      for (auto& w : split(line)) out.push_back(std::move(w));
    }
    return out;
  }

  // Reads n numbers that may span lines; the rest of the last line is dropped.
  std::vector<double> doubles(std::size_t n, const std::string& what) {
    std::vector<double> out;
    out.reserve(n);
    while (out.size() < n) {
      std::string line;
      if (!next_data_line(line))
        fail(fmt::format("unexpected end of file after {} of the {} values of {}", out.size(), n,
                         what));
      for (const auto& w : split(line)) {
        if (out.size() == n) break;
        out.push_back(to_double(w, what));
      }
    }
    return out;
  }

  // A number; Fortran "D" exponents are read as "E" (see the header).
  double to_double(std::string word, const std::string& what) const {
    std::replace(word.begin(), word.end(), 'D', 'E');
    std::replace(word.begin(), word.end(), 'd', 'e');
    const char* first = word.data();
    if (*first == '+') ++first;
    double value = 0;
    const auto [end, ec] = std::from_chars(first, word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size())
      fail(fmt::format("expected a number in {}, found '{}'", what, word));
    if (!std::isfinite(value)) fail(fmt::format("expected a finite number in {}, found '{}'", what, word));
    return value;
  }

  int to_int(const std::string& word, const std::string& what) const {
    int value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size())
      fail(fmt::format("expected an integer {}, found '{}'", what, word));
    return value;
  }

 private:
  bool next_data_line(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_number_;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    return true;
  }

  std::string name_;
  std::ifstream in_;
  std::uintmax_t bytes_ = 0;
  int line_number_ = 0;
};

EamGrid read_grid(Records& in) {
  const std::string what = "the grid line 'Nrho drho Nr dr cutoff'";
  const auto w = in.words(5, what);
  EamGrid g;
  g.nrho = in.to_int(w[0], "Nrho");
  g.drho = in.to_double(w[1], "drho");
  g.nr = in.to_int(w[2], "Nr");
  g.dr = in.to_double(w[3], "dr");
  g.cut = in.to_double(w[4], "cutoff");
  if (g.nrho < kMinTableLength || g.nr < kMinTableLength)
    in.fail(fmt::format("expected Nrho and Nr >= {}, found Nrho = {}, Nr = {}", kMinTableLength,
                        g.nrho, g.nr));
  if (static_cast<std::uintmax_t>(std::max(g.nrho, g.nr)) > in.max_values())
    in.fail(fmt::format("tables of Nrho = {} and Nr = {} values cannot fit in a file of {} bytes",
                        g.nrho, g.nr, in.max_values() * kMinValueBytes));
  if (!(g.drho > 0) || !(g.dr > 0) || !(g.cut > 0))
    in.fail(fmt::format("expected drho, dr and cutoff > 0, found {}, {}, {}", g.drho, g.dr, g.cut));
  // The tables' extents (Nrho - 1) drho and (Nr - 1) dr size the common grid: an infinite one
  // (dr = 1e308) would overflow its integer count.
  if (!std::isfinite(g.nrho * g.drho) || !std::isfinite(g.nr * g.dr))
    in.fail(fmt::format("the tables' extents Nrho drho = {} x {} and Nr dr = {} x {} are not finite",
                        g.nrho, g.drho, g.nr, g.dr));
  if (g.cut > kMaxCutoff)
    in.fail(fmt::format("cutoff {} Å is beyond {} Å, longer than any EAM potential's", g.cut, kMaxCutoff));
  // The tables reach r = (Nr - 1) dr; files commonly put the cutoff one step further, at Nr dr.
  const double table_end = g.nr * g.dr;
  if (g.cut > table_end * (1 + 1e-9))
    in.fail(fmt::format("cutoff {} Å lies beyond the tabulated range Nr dr = {} x {} = {} Å", g.cut,
                        g.nr, g.dr, table_end));
  if (g.drho < kMinSpacing || g.dr < kMinSpacing)
    in.fail(fmt::format("table spacings drho = {} and dr = {} must be >= {}: finer ones cannot be resolved (the "
                        "splines' slopes divide differences of values rounded at 1e-16 by the spacing)",
                        g.drho, g.dr, kMinSpacing));
  return g;
}

double read_mass(Records& in, const std::string& what) {
  const auto w = in.words(2, fmt::format("the line 'Z mass ...' of {}", what));
  in.to_int(w[0], fmt::format("atomic number Z of {}", what));
  const double mass = in.to_double(w[1], fmt::format("the mass of {}", what));
  if (!(mass >= kMinMass && mass <= kMaxMass))
    in.fail(fmt::format("expected an atomic mass in [{}, {}] amu for {}, found {}", kMinMass, kMaxMass,
                        what, mass));
  return mass;
}

// One table of Nr values per element pair i >= j, in the order (0,0) (1,0) (1,1) (2,0) ...
std::vector<std::vector<double>> read_pair_tables(Records& in, const SetflFile& s, const std::string& what) {
  std::vector<std::vector<double>> tables;
  const auto n = s.elements.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      tables.push_back(in.doubles(static_cast<std::size_t>(s.grid.nr),
                                  fmt::format("{} of {}-{}", what, s.elements[i], s.elements[j])));
  return tables;
}

}  // namespace

int SetflFile::element_index(const std::string& name) const {
  const auto it = std::find(elements.begin(), elements.end(), name);
  return it == elements.end() ? -1 : static_cast<int>(it - elements.begin());
}

FuncflFile read_funcfl(const std::filesystem::path& file) {
  Records in(file);
  FuncflFile f;
  f.path = file.string();
  in.skip_line("a comment line");
  f.mass = read_mass(in, "the element");
  f.grid = read_grid(in);
  f.frho = in.doubles(static_cast<std::size_t>(f.grid.nrho), "F(rho)");
  f.zr = in.doubles(static_cast<std::size_t>(f.grid.nr), "Z(r)");
  f.rhor = in.doubles(static_cast<std::size_t>(f.grid.nr), "rho(r)");
  return f;
}

namespace {

// The setfl (or fs) records of `in`, from its first line up to the last r*phi table.
SetflFile read_setfl_records(Records& in, const std::filesystem::path& file, bool finnis_sinclair) {
  SetflFile s;
  s.path = file.string();
  s.finnis_sinclair = finnis_sinclair;
  for (int k = 0; k < 3; ++k) in.skip_line("three comment lines");
  const auto w = in.words(1, "the element line 'N element_1 ... element_N'");
  const int n = in.to_int(w[0], "number of elements N");
  if (n < 1 || static_cast<std::size_t>(n) + 1 != w.size())
    in.fail(fmt::format("expected 'N' followed by N element names, found N = {} and {} names",
                        w[0], w.size() - 1));
  s.elements.assign(w.begin() + 1, w.end());
  s.grid = read_grid(in);
  const auto nrho = static_cast<std::size_t>(s.grid.nrho), nr = static_cast<std::size_t>(s.grid.nr);
  for (int i = 0; i < n; ++i) {
    const std::string& el = s.elements[static_cast<std::size_t>(i)];
    s.mass.push_back(read_mass(in, "element " + el));
    s.frho.push_back(in.doubles(nrho, "F(rho) of " + el));
    if (finnis_sinclair) {
      for (int j = 0; j < n; ++j)
        s.rhor.push_back(in.doubles(nr, fmt::format("rho_{},{}(r)", el, s.elements[j])));
    } else {
      s.rhor.push_back(in.doubles(nr, "rho(r) of " + el));
    }
  }
  s.z2r = read_pair_tables(in, s, "r*phi(r)");
  return s;
}

}  // namespace

SetflFile read_setfl(const std::filesystem::path& file, bool finnis_sinclair) {
  Records in(file);
  return read_setfl_records(in, file, finnis_sinclair);
}

AdpFile read_adp(const std::filesystem::path& file) {
  Records in(file);
  AdpFile a;
  a.setfl = read_setfl_records(in, file, false);
  a.u2r = read_pair_tables(in, a.setfl, "the ADP dipole function u(r)");
  a.w2r = read_pair_tables(in, a.setfl, "the ADP quadrupole function w(r)");
  return a;
}

}  // namespace shockfield::md::potentials
