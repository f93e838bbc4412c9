// Point-set readers (point_file.hpp).
#include "shockfield/geometry/point_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/core/unit_names.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/io/line_reader.hpp"

namespace shockfield::geometry {
namespace {

/// Words of a CSV/text line: commas and blanks both separate values.
std::vector<std::string> csv_words(const std::string& line) {
  std::string text = line.substr(0, line.find('#'));
  std::replace(text.begin(), text.end(), ',', ' ');
  std::vector<std::string> out;
  for (auto w : io::split_words(text)) out.emplace_back(w);
  return out;
}

// The largest coordinate magnitude: the exact orientation and in-sphere predicates of the
// Delaunay division multiply up to five coordinate differences, so beyond 1e50 their products
// would overflow a double (a point at 1e308 reached the space tree as a non-finite coordinate).
constexpr double kMaxCoordinate = 1e50;

double coordinate(const io::LineReader& in, std::string_view word, int k) {
  const double v = in.to_double(word, fmt::format("coordinate {}", "xyz"[k]));
  if (!(std::abs(v) <= kMaxCoordinate))
    in.fail(fmt::format("coordinate {} = {} is not a finite number of magnitude at most {:g}", "xyz"[k], v,
                        kMaxCoordinate));
  return v;
}

bool is_number_start(const std::string& w) {
  const char c = w.empty() ? ' ' : w[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' ||
         w == "nan" || w == "NaN" || w == "inf";
}

template <int N>
std::vector<std::array<double, N>> read_csv(const std::filesystem::path& file) {
  io::LineReader in(file);
  std::array<std::size_t, N> column;
  for (int k = 0; k < N; ++k) column[k] = k;
  bool first = true;
  std::vector<std::array<double, N>> pts;
  while (in.next()) {
    const auto w = csv_words(in.line());
    if (w.empty()) continue;
    if (first && !is_number_start(w[0])) {
      // A header: take x, y, z by name when present.
      const char* names[3] = {"x", "y", "z"};
      for (int k = 0; k < N; ++k) {
        const auto it = std::find(w.begin(), w.end(), names[k]);
        if (it != w.end()) column[k] = it - w.begin();
      }
      first = false;
      continue;
    }
    first = false;
    std::array<double, N> p;
    for (int k = 0; k < N; ++k) {
      if (column[k] >= w.size())
        in.fail(fmt::format("expected at least {} values per line, got {}", column[k] + 1,
                            w.size()));
      p[k] = coordinate(in, w[column[k]], k);
    }
    pts.push_back(p);
  }
  return pts;
}

template <int N>
std::vector<std::array<double, N>> read_xyz(const std::filesystem::path& file) {
  io::LineReader in(file);
  in.require_next("the atom count");
  const auto count_words = in.words();
  if (count_words.empty()) in.fail("expected the atom count on the first line");
  const long long n = in.to_int(count_words[0], "the atom count");
  if (n < 0) in.fail("the atom count is negative");
  in.require_next("the comment line");
  std::vector<std::array<double, N>> pts;
  for (long long i = 0; i < n; ++i) {
    in.require_next(fmt::format("atom {} of {}", i + 1, n));
    const auto w = in.words();
    if (w.size() < 4) in.fail("expected 'species x y z'");
    std::array<double, N> p;
    for (int k = 0; k < N; ++k) p[k] = coordinate(in, w[1 + k], k);
    pts.push_back(p);
  }
  return pts;
}

template <int N>
PointSet<N> read_dump_points(const std::filesystem::path& file, int frame) {
  const auto frames = io::read_dump(file);
  if (frames.empty()) throw InputError(fmt::format("{}: no frame in the dump file", file.string()));
  const int f = frame < 0 ? static_cast<int>(frames.size()) - 1 : frame;
  if (f >= static_cast<int>(frames.size()))
    throw InputError(fmt::format("{}: frame {} asked for, the dump has {}", file.string(), frame,
                                 frames.size()));
  PointSet<N> set{{}, frames[f].units.empty() ? "" : units::lammps_length_unit(frames[f].units), true};
  if (!frames[f].units.empty() && set.length_unit.empty())
    throw InputError(fmt::format("{}: frame {}: ITEM: UNITS '{}' is not a LAMMPS unit style ({})", file.string(), f,
                                 frames[f].units, units::kLammpsUnitStyles));
  auto& pts = set.points;
  for (const auto& v : frames[f].positions()) {
    std::array<double, N> p;
    for (int k = 0; k < N; ++k) {
      if (!(std::abs(v[k]) <= kMaxCoordinate))
        throw InputError(fmt::format("{}: frame {}: coordinate {} = {} is not a finite number of magnitude at most {:g}",
                                     file.string(), f, "xyz"[k], v[k], kMaxCoordinate));
      p[k] = v[k];
    }
    pts.push_back(p);
  }
  return set;
}

bool looks_like_dump(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  return std::getline(in, line) && line.rfind("ITEM:", 0) == 0;
}

}  // namespace

template <int N>
PointSet<N> read_points(const std::filesystem::path& file, int frame) {
  if (!std::filesystem::is_regular_file(file))
    throw InputError(fmt::format("{}: no such file", file.string()));
  if (looks_like_dump(file)) return read_dump_points<N>(file, frame);
  const std::string ext = file.extension().string();
  if (ext == ".xyz" || ext == ".extxyz") return {read_xyz<N>(file), "", false};
  return {read_csv<N>(file), "", false};
}

template PointSet<2> read_points<2>(const std::filesystem::path&, int);
template PointSet<3> read_points<3>(const std::filesystem::path&, int);

}  // namespace shockfield::geometry
