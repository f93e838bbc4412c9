#include "shockfield/md/potentials/pair_table_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include "shockfield/core/error.hpp"
#include "shockfield/io/line_reader.hpp"

namespace shockfield::md::potentials {
namespace {

// A data line "i r e f" takes at least 8 bytes: a longer table cannot be in the file, and is
// refused before anything is sized by it.
constexpr std::uintmax_t kMinLineBytes = 8;

// The words of the current line without its comment (text from '#' on, as LAMMPS's
// TextFileReader strips it).
std::vector<std::string_view> data_words(const io::LineReader& in) {
  std::string_view line = in.line();
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  return io::split_words(line);
}

// Advances to the next line with words; false at the end of the file.
bool next_words(io::LineReader& in, std::vector<std::string_view>& words) {
  while (in.next()) {
    words = data_words(in);
    if (!words.empty()) return true;
  }
  return false;
}

// The parameter line "N n [R|RSQ rlo rhi] [FPRIME fplo fphi]" (pair_table.cpp param_extract).
void read_parameters(const io::LineReader& in, std::uintmax_t file_bytes, PairTableSection& s) {
  const auto words = data_words(in);
  std::optional<long long> n;
  const auto value = [&](std::size_t k, const std::string& what) {
    if (k >= words.size()) in.fail(fmt::format("expected {} after '{}'", what, words[k - 1]));
    return in.to_double(words[k], what);
  };
  for (std::size_t k = 0; k < words.size(); ++k) {
    const std::string_view w = words[k];
    if (w == "N") {
      if (k + 1 >= words.size()) in.fail("expected the number of table lines after 'N'");
      n = in.to_int(words[++k], "the number of table lines after 'N'");
    } else if (w == "R" || w == "RSQ") {
      s.spacing = w == "R" ? PairTableSection::Spacing::r : PairTableSection::Spacing::rsq;
      s.rlo = value(k + 1, fmt::format("the inner distance rlo after '{}'", w));
      s.rhi = value(k + 2, fmt::format("the outer distance rhi after '{}'", w));
      k += 2;
      if (!(s.rlo > 0 && s.rhi > s.rlo))
        in.fail(fmt::format("expected 0 < rlo < rhi after '{}', found {} {}", w, s.rlo, s.rhi));
    } else if (w == "FPRIME") {
      s.has_fprime = true;
      s.fplo = value(k + 1, "dF/dr at the first point after 'FPRIME'");
      s.fphi = value(k + 2, "dF/dr at the last point after 'FPRIME'");
      k += 2;
    } else if (w == "BITMAP") {
      in.fail("BITMAP tables (pair_style table bitmap) are not supported: tabulate the section "
              "with N and R or RSQ, or with a distance column");
    } else {
      in.fail(fmt::format("expected a table parameter N, R, RSQ or FPRIME, found '{}'", w));
    }
  }
  if (!n) in.fail(fmt::format("expected the parameter line 'N n [R rlo rhi | RSQ rlo rhi] "
                              "[FPRIME fplo fphi]' of section {}", s.keyword));
  // LAMMPS refuses tables of one line (PairTable::coeff, "Invalid pair table length").
  if (*n < 2) in.fail(fmt::format("expected N >= 2 table lines, found N = {}", *n));
  if (static_cast<std::uintmax_t>(*n) > file_bytes / kMinLineBytes)
    in.fail(fmt::format("a table of N = {} lines cannot fit in a file of {} bytes", *n, file_bytes));
  s.r.resize(static_cast<std::size_t>(*n));
  s.e.resize(s.r.size());
  s.f.resize(s.r.size());
}

// The distance of line i (0-based) as LAMMPS computes it for R and RSQ, in its order of operations.
double spaced_r(const PairTableSection& s, std::size_t i, double from_file) {
  const double k = static_cast<double>(i), intervals = static_cast<double>(s.r.size() - 1);
  switch (s.spacing) {
    case PairTableSection::Spacing::r:
      return s.rlo + (s.rhi - s.rlo) * k / intervals;
    case PairTableSection::Spacing::rsq:
      return std::sqrt(s.rlo * s.rlo + (s.rhi * s.rhi - s.rlo * s.rlo) * k / intervals);
    case PairTableSection::Spacing::file:
      break;
  }
  return from_file;
}

void read_values(io::LineReader& in, PairTableSection& s) {
  in.require_next(fmt::format("a blank line after the parameter line of section {}", s.keyword));
  if (!data_words(in).empty())
    in.fail(fmt::format("expected a blank line after the parameter line of section {} (LAMMPS "
                        "skips this line)", s.keyword));
  std::vector<std::string_view> w;
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    if (!next_words(in, w))
      in.fail(fmt::format("unexpected end of file after {} of the {} lines of section {}", i,
                          s.r.size(), s.keyword));
    if (w.size() < 4) in.fail(fmt::format("expected 'index r energy force', found {} words", w.size()));
    in.to_int(w[0], "the line index");
    const double r = in.to_double(w[1], "the distance r");
    s.e[i] = in.to_double(w[2], "the energy");
    s.f[i] = in.to_double(w[3], "the force");
    s.r[i] = spaced_r(s, i, r);
    if (s.spacing == PairTableSection::Spacing::file) {
      if (!(s.r[i] > 0)) in.fail(fmt::format("expected a distance r > 0, found {}", s.r[i]));
      if (i > 0 && !(s.r[i] > s.r[i - 1]))
        in.fail(fmt::format("expected distances increasing line by line, found r = {} after {}",
                            s.r[i], s.r[i - 1]));
    }
  }
}

}  // namespace

PairTableSection read_pair_table(const std::filesystem::path& file, const std::string& keyword) {
  io::LineReader in(file);
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  std::vector<std::string> seen;
  std::vector<std::string_view> w;
  while (next_words(in, w)) {
    PairTableSection s;
    s.path = file.string();
    s.keyword = std::string(w[0]);
    in.require_next(fmt::format("the parameter line of section {}", s.keyword));
    read_parameters(in, ec ? 0 : bytes, s);
    if (s.keyword == keyword) {
      read_values(in, s);
      return s;
    }
    // Another section: skip its blank line and n value lines.
    in.require_next(fmt::format("a blank line after the parameter line of section {}", s.keyword));
    for (std::size_t i = 0; i < s.r.size(); ++i)
      if (!next_words(in, w))
        in.fail(fmt::format("unexpected end of file in section {}", s.keyword));
    seen.push_back(s.keyword);
  }
  throw InputError(fmt::format("{}: no table section '{}' (sections in the file: {})", file.string(),
                               keyword, seen.empty() ? "none" : fmt::format("{}", fmt::join(seen, ", "))));
}

}  // namespace shockfield::md::potentials
