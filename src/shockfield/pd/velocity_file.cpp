#include "shockfield/pd/velocity_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {
namespace {

// The line without its comment, or empty when nothing is left but blanks.
std::string content(std::string line) {
  if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
  if (line.find_first_not_of(" \t\r") == std::string::npos) return {};
  return line;
}

// Six comma-separated numbers, or false.
bool read_row(const std::string& line, std::array<double, 6>& row) {
  std::istringstream fields(line);
  for (std::size_t k = 0; k < row.size(); ++k) {
    if (!(fields >> row[k])) return false;
    fields >> std::ws;
    if (k + 1 < row.size() && fields.get() != ',') return false;
  }
  std::string extra;
  return !(fields >> extra);
}

}  // namespace

std::vector<Vec3> read_point_velocities(const std::filesystem::path& file, int dim,
                                        const std::vector<Vec3>& points, double spacing) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the velocity file", file.string()));
  const std::string name = file.string();
  std::vector<Vec3> velocity;
  bool header = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = content(line);
    if (text.empty()) continue;
    if (!header) {
      std::string compact;
      for (char c : text)
        if (c != ' ' && c != '\t' && c != '\r') compact += c;
      if (compact != "x,y,z,vx,vy,vz")
        throw InputError(fmt::format("{}:{}: expected the header 'x,y,z,vx,vy,vz', got '{}'", name,
                                     number, text));
      header = true;
      continue;
    }
    std::array<double, 6> row{};
    if (!read_row(text, row))
      throw InputError(fmt::format("{}:{}: expected six numbers 'x,y,z,vx,vy,vz', got '{}'", name,
                                   number, text));
    const std::size_t i = velocity.size();
    if (i == points.size())
      throw InputError(fmt::format("{}:{}: more rows than the {} points the region selects", name,
                                   number, points.size()));
    const Vec3 x(row[0], row[1], row[2]), v(row[3], row[4], row[5]);
    if (!((x - points[i]).cwiseAbs().maxCoeff() <= 1e-6 * spacing))
      throw InputError(fmt::format(
          "{}:{}: the position ({}, {}, {}) m is not that of the region's point {} ({}, {}, "
          "{}) m (expected the selected points in point order, x fastest, to 1e-6 of the "
          "spacing)",
          name, number, x[0], x[1], x[2], i, points[i][0], points[i][1], points[i][2]));
    if (!v.allFinite())
      throw InputError(fmt::format("{}:{}: a velocity that is not a finite number", name, number));
    for (int d = dim; d < 3; ++d)
      if (v[d] != 0.0)
        throw InputError(fmt::format("{}:{}: velocity component {} of a {}D body must be 0", name,
                                     number, d, dim));
    velocity.push_back(v);
  }
  if (velocity.size() != points.size())
    throw InputError(fmt::format(
        "{}: {} velocity rows for the {} points the region selects (expected one per point)", name,
        velocity.size(), points.size()));
  return velocity;
}

}  // namespace shockfield::pd
