#include "shockfield/pd/family.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/cell_list.hpp"

namespace shockfield::pd {

VolumeCorrection volume_correction_from_name(const std::string& name) {
  if (name == "none") return VolumeCorrection::none;
  if (name == "linear") return VolumeCorrection::linear;
  throw InputError(fmt::format("unknown volume correction '{}' (expected none or linear)", name));
}

Family build_family(const PointCloud& cloud, double horizon, VolumeCorrection correction) {
  if (!std::isfinite(horizon) || horizon < cloud.spacing * (1.0 - 1e-12))
    throw InputError(fmt::format("pd horizon δ = {} m is smaller than the spacing ΔX = {} m (expected δ = m·ΔX, m >= 1)",
                                 horizon, cloud.spacing));
  const std::size_t n = cloud.size();
  auto [lo, hi] = cloud.bounds();
  geometry::CellList cells;
  cells.build(cloud.x, n, lo, hi, horizon * (1.0 + 1e-9));  // wider than the cut-off, so ±1 cell holds it
  const auto dims = cells.dims();
  const double cut2 = horizon * horizon * (1.0 + 1e-12);  // a neighbour at exactly δ = m·ΔX belongs
  const double half = 0.5 * cloud.spacing;

  std::vector<std::vector<int>> lists(n);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t si = 0; si < static_cast<std::ptrdiff_t>(n); ++si) {
    const auto i = static_cast<std::size_t>(si);
    const auto c = cells.cell_coords(cells.cell_of(cloud.x[i]));
    auto& list = lists[i];
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = c[0] + dx, cy = c[1] + dy, cz = c[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= dims[0] || cy >= dims[1] || cz >= dims[2]) continue;
          const int cell = cells.cell_index(cx, cy, cz);
          for (int k = cells.cell_start()[cell]; k < cells.cell_start()[cell + 1]; ++k) {
            const int j = cells.cell_points()[k];
            if (static_cast<std::size_t>(j) == i) continue;
            if ((cloud.x[j] - cloud.x[i]).squaredNorm() <= cut2) list.push_back(j);
          }
        }
    std::sort(list.begin(), list.end());
  }

  Family family;
  family.horizon = horizon;
  family.offset.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) family.offset[i + 1] = family.offset[i] + static_cast<int>(lists[i].size());
  const auto nb = static_cast<std::size_t>(family.offset[n]);
  family.neighbor.resize(nb);
  family.length.resize(nb);
  family.volume_scale.resize(nb);
  for (std::size_t i = 0; i < n; ++i) {
    int b = family.offset[i];
    for (int j : lists[i]) {
      const double r0 = (cloud.x[j] - cloud.x[i]).norm();
      family.neighbor[b] = j;
      family.length[b] = r0;
      family.volume_scale[b] = (correction == VolumeCorrection::linear && std::abs(r0 - horizon) <= half)
                                   ? (horizon + half - r0) / cloud.spacing
                                   : 1.0;
      ++b;
    }
  }
  return family;
}

}  // namespace shockfield::pd
