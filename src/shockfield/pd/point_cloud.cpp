#include "shockfield/pd/point_cloud.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {
namespace {

void check_dim_spacing(int dim, double spacing, const std::string& where) {
  if (dim < 1 || dim > 3) throw InputError(fmt::format("{}: dimension {} (expected 1, 2 or 3)", where, dim));
  if (!(spacing > 0.0)) throw InputError(fmt::format("{}: spacing {} (expected > 0 m)", where, spacing));
}

}  // namespace

std::pair<Vec3, Vec3> PointCloud::bounds() const {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (x.empty()) lo = hi = Vec3::Zero();
  return {lo, hi};
}

PointCloud lattice_cloud(int dim, const std::array<int, 3>& counts, double spacing, const Vec3& origin) {
  check_dim_spacing(dim, spacing, "pd lattice");
  for (int d = 0; d < 3; ++d) {
    if (counts[d] < 1) throw InputError(fmt::format("pd lattice: {} points along axis {} (expected >= 1)", counts[d], d));
    if (d >= dim && counts[d] != 1)
      throw InputError(fmt::format("pd lattice: {} points along axis {} of a {}D body (expected 1)", counts[d], d, dim));
  }
  PointCloud cloud;
  cloud.dim = dim;
  cloud.spacing = spacing;
  const std::size_t n = static_cast<std::size_t>(counts[0]) * counts[1] * counts[2];
  cloud.x.reserve(n);
  for (int k = 0; k < counts[2]; ++k)
    for (int j = 0; j < counts[1]; ++j)
      for (int i = 0; i < counts[0]; ++i) cloud.x.push_back(origin + spacing * Vec3(i, j, k));
  cloud.volume.assign(n, std::pow(spacing, dim));
  return cloud;
}

PointCloud read_cloud(const std::filesystem::path& file, int dim, double spacing) {
  check_dim_spacing(dim, spacing, file.string());
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the point file", file.string()));
  PointCloud cloud;
  cloud.dim = dim;
  cloud.spacing = spacing;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    Vec3 p;
    double v = 0.0;
    std::string extra;
    if (!(fields >> p[0] >> p[1] >> p[2] >> v) || (fields >> extra))
      throw InputError(fmt::format("{}:{}: expected 'x y z volume', got '{}'", file.string(), number, line));
    // Finite and within 1e50 m (so that the extent, the cell lists and the volume sums stay finite).
    if (!(v > 0.0 && v <= 1e50))
      throw InputError(fmt::format("{}:{}: volume {} (expected > 0 and at most 1e50)", file.string(), number, v));
    for (int d = 0; d < 3; ++d)
      if (!(std::abs(p[d]) <= 1e50))
        throw InputError(fmt::format("{}:{}: coordinate {} = {} (expected a number within +-1e50 m)", file.string(),
                                     number, d, p[d]));
    for (int d = dim; d < 3; ++d)
      if (p[d] != 0.0)
        throw InputError(fmt::format("{}:{}: coordinate {} of a {}D body must be 0", file.string(), number, d, dim));
    cloud.x.push_back(p);
    cloud.volume.push_back(v);
  }
  if (cloud.x.empty()) throw InputError(fmt::format("{}: no points", file.string()));
  return cloud;
}

}  // namespace shockfield::pd
