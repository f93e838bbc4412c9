#include "shockfield/pd/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {
namespace {
// LAMMPS's constants (pair_peri_pmb.cpp): the reach factors 0.9 and 1.35 and the force factor 15.
constexpr double kReachOfBond = 0.9, kReachOfSpacing = 1.35, kForceFactor = 15.0;
// Verlet skin as a fraction of the spacing: a rebuild every ~0.15·ΔX of motion of some point.
constexpr double kSkin = 0.3;
}  // namespace

ShortRangeContact::ShortRangeContact(const PointCloud& cloud, double micromodulus, double horizon)
    : cloud_(cloud), constant_(kForceFactor * micromodulus / horizon),
      max_reach_(kReachOfSpacing * cloud.spacing), skin_(kSkin * cloud.spacing) {
  if (!(micromodulus > 0.0) || !(horizon > 0.0) || !(cloud.spacing > 0.0))
    throw InputError(fmt::format("pd contact: micromodulus {}, horizon {} m and spacing {} m must be > 0", micromodulus,
                                 horizon, cloud.spacing));
}

void ShortRangeContact::update(const std::vector<Vec3>& y) {
  bool stale = y_built_.size() != y.size();
  if (!stale) {
    const double limit2 = 0.25 * skin_ * skin_;
    const auto n = static_cast<std::ptrdiff_t>(y.size());
#pragma omp parallel for schedule(static) reduction(|| : stale)
    for (std::ptrdiff_t i = 0; i < n; ++i) stale = stale || (y[i] - y_built_[i]).squaredNorm() > limit2;
  }
  if (stale) build(y);
}

void ShortRangeContact::build(const std::vector<Vec3>& y) {
  geometry::build_neighbor_list(y, y.size(), max_reach_ + skin_, false, list_);
  reach_.resize(list_.pairs());
  const auto n = static_cast<std::ptrdiff_t>(y.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t si = 0; si < n; ++si) {
    const auto i = static_cast<std::size_t>(si);
    // Partners by index, so the sum of force_density runs in an order fixed by the pairs alone.
    std::sort(list_.neighbors.begin() + list_.offset[i], list_.neighbors.begin() + list_.offset[i + 1]);
    for (auto k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list_.neighbors[static_cast<std::size_t>(k)]);
      reach_[static_cast<std::size_t>(k)] = std::min(kReachOfBond * (cloud_.x[j] - cloud_.x[i]).norm(), max_reach_);
    }
  }
  y_built_ = y;
  ++builds_;
}

double ShortRangeContact::energy(const std::vector<Vec3>& y) {
  update(y);
  double u = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i)
    for (auto k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list_.neighbors[static_cast<std::size_t>(k)]);
      const double gap = reach_[static_cast<std::size_t>(k)] - (y[i] - y[j]).norm();
      // Each pair is listed from both ends: half the pair energy 15c·V_i·V_j·gap²/(2δ) each.
      if (gap > 0.0) u += 0.25 * constant_ * cloud_.volume[i] * cloud_.volume[j] * gap * gap;
    }
  return u;
}

std::size_t ShortRangeContact::active_pairs(const std::vector<Vec3>& y) {
  update(y);
  std::size_t count = 0;
  for (std::size_t i = 0; i < y.size(); ++i)
    for (auto k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list_.neighbors[static_cast<std::size_t>(k)]);
      if (j > i && (y[i] - y[j]).norm() < reach_[static_cast<std::size_t>(k)]) ++count;
    }
  return count;
}

}  // namespace shockfield::pd
