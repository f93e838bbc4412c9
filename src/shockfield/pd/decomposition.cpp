#include "shockfield/pd/decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {
namespace {

// Every point's cell [x − ΔX/2, x + ΔX/2) along each axis: the box the ranks cut (not periodic).
std::array<parallel::AxisSpan, 3> body_spans(const PointCloud& cloud) {
  const auto [lo, hi] = cloud.bounds();
  const double half = 0.5 * cloud.spacing;
  std::array<parallel::AxisSpan, 3> spans;
  for (int d = 0; d < 3; ++d) spans[d] = {lo[d] - half, hi[d] + half, false};
  return spans;
}

// A bond reaches δ·(1 + 5e-13) at most (family.cpp's cut-off): the ghosts reach a little further.
double ghost_reach(double horizon) { return horizon * (1.0 + 1e-9); }

// The local points: owned ones and their ghosts, by index in the whole body and reference position.
struct LocalPoints {
  static constexpr int ghost_width = 4;  // index, x, y, z
  std::vector<std::size_t> origin;
  std::vector<Vec3> x;
  std::size_t size() const { return origin.size(); }
  double coordinate(std::size_t i, int axis) const { return x[i][axis]; }
  void pack_ghost(std::size_t i, int /*axis*/, int /*periods*/, double* out) const {
    out[0] = static_cast<double>(origin[i]);
    for (int d = 0; d < 3; ++d) out[1 + d] = x[i][d];
  }
  void append_ghosts(const double* in, std::size_t count, bool /*from_self*/) {
    for (std::size_t k = 0; k < count; ++k, in += ghost_width) {
      origin.push_back(static_cast<std::size_t>(in[0]));
      x.emplace_back(in[1], in[2], in[3]);
    }
  }
};

}  // namespace

parallel::Dims3 pd_rank_grid(const PointCloud& cloud, double horizon, int ranks, const parallel::Dims3& given) {
  const auto spans = body_spans(cloud);
  parallel::Cells3 pieces{1, 1, 1};
  for (int d = 0; d < 3; ++d)
    pieces[d] = std::max(1LL, static_cast<long long>(std::floor((spans[d].hi - spans[d].lo) / ghost_reach(horizon))));
  const bool chosen = given == parallel::Dims3{0, 0, 0};
  try {
    if (chosen) return parallel::choose_rank_grid(pieces, ranks, 1);
    parallel::check_rank_grid(given, pieces, ranks, 1);
    return given;
  } catch (const InputError&) {
    if (!chosen && static_cast<long long>(given[0]) * given[1] * given[2] != ranks) throw;
    throw InputError(fmt::format(
        "{} ranks cannot cut the body ({:.4g} x {:.4g} x {:.4g} m) into pieces at least {:.4g} m long (the horizon "
        "δ: a bond's partner must lie on a neighbouring rank) along every cut axis{}; at most {} x {} x {} = {} ranks "
        "fit",
        ranks, spans[0].hi - spans[0].lo, spans[1].hi - spans[1].lo, spans[2].hi - spans[2].lo, horizon,
        chosen ? "" : fmt::format(" as --rank-grid {}x{}x{}", given[0], given[1], given[2]), pieces[0], pieces[1],
        pieces[2], pieces[0] * pieces[1] * pieces[2]));
  }
}

Decomposition::Decomposition(const parallel::Communicator& world, const parallel::Dims3& dims, const PointCloud& cloud,
                             const Family& family)
    : dims_(dims),
      exchange_(world.cartesian(dims, {false, false, false}), body_spans(cloud),
                {ghost_reach(family.horizon), ghost_reach(family.horizon), ghost_reach(family.horizon)}) {
  const std::array<int, 3> mine = comm().coordinates();
  LocalPoints points;
  for (std::size_t g = 0; g < cloud.size(); ++g) {
    bool own = true;
    for (int d = 0; d < 3; ++d) own = own && exchange_.owner_along(d, cloud.x[g][d]) == mine[d];
    if (!own) continue;
    points.origin.push_back(g);
    points.x.push_back(cloud.x[g]);
  }
  owned_ = points.size();
  if (exchange_.total(owned_) != static_cast<long long>(cloud.size()))  // every point owned once
    throw RunError(fmt::format("pd decomposition: the ranks own {} of the body's {} points", exchange_.total(owned_),
                               cloud.size()));
  swaps_ = exchange_.build_ghosts(points, {0, 0, 0});
  point_origin_ = std::move(points.origin);

  cloud_.dim = cloud.dim;
  cloud_.spacing = cloud.spacing;
  std::unordered_map<std::size_t, int> local_of;
  for (std::size_t l = 0; l < point_origin_.size(); ++l) {
    const std::size_t g = point_origin_[l];
    cloud_.x.push_back(cloud.x[g]);
    cloud_.volume.push_back(cloud.volume[g]);
    local_of.emplace(g, static_cast<int>(l));
  }
  family_.horizon = family.horizon;
  family_.offset.assign(point_origin_.size() + 1, 0);
  for (std::size_t l = 0; l < point_origin_.size(); ++l) {
    const std::size_t g = point_origin_[l];
    for (int b = family.begin(g); b < family.end(g); ++b) {
      const auto j = local_of.find(static_cast<std::size_t>(family.neighbor[b]));
      if (j == local_of.end()) {
        if (l < owned_)  // cannot happen: the ghosts hold every point within δ of the piece
          throw RunError(fmt::format("pd decomposition: point {} is bonded to point {}, not on its rank", g,
                                     family.neighbor[b]));
        continue;
      }
      family_.neighbor.push_back(j->second);
      family_.length.push_back(family.length[b]);
      family_.volume_scale.push_back(family.volume_scale[b]);
      bond_origin_.push_back(static_cast<std::size_t>(b));
    }
    family_.offset[l + 1] = static_cast<int>(family_.neighbor.size());
  }
}

void Decomposition::forward(std::vector<double>& values) const {
  exchange_.forward(
      swaps_, 1, [&](std::size_t i, const parallel::GhostSwap&, double* out) { out[0] = values[i]; },
      [&](std::size_t i, const double* in) { values[i] = in[0]; });
}

void Decomposition::forward(std::vector<Vec3>& y, std::vector<Vec3>& v) const {
  exchange_.forward(
      swaps_, 6,
      [&](std::size_t i, const parallel::GhostSwap&, double* out) {
        for (int d = 0; d < 3; ++d) out[d] = y[i][d], out[3 + d] = v[i][d];
      },
      [&](std::size_t i, const double* in) {
        y[i] = Vec3(in[0], in[1], in[2]);
        v[i] = Vec3(in[3], in[4], in[5]);
      });
}

}  // namespace shockfield::pd
