#include "shockfield/analysis/atoms/cluster_tracking.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "shockfield/core/error.hpp"
#include "shockfield/analysis/line_fit.hpp"

namespace shockfield::analysis::atoms {
namespace {

std::size_t shared(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b) {
  std::size_t n = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
    if (*i < *j) ++i;
    else if (*j < *i) ++j;
    else ++n, ++i, ++j;
  }
  return n;
}

}  // namespace

void ClusterTracker::add(std::size_t frame, long long timestep, const std::vector<std::int64_t>& ids,
                         const ClusterResult& result) {
  const std::size_t count = result.clusters.size();
  std::vector<std::vector<std::int64_t>> members(count);
  for (std::size_t i = 0; i < result.cluster_of.size(); ++i)
    if (result.cluster_of[i] >= 0)
      members[static_cast<std::size_t>(result.cluster_of[i])].push_back(ids.empty() ? std::int64_t(i + 1) : ids[i]);
  for (auto& m : members) std::sort(m.begin(), m.end());
  // Candidate continuations (shared atoms, previous cluster, new cluster), most shared first.
  std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> pairs;
  for (std::size_t p = 0; p < previous_members_.size(); ++p)
    for (std::size_t k = 0; k < count; ++k)
      if (const std::size_t n = shared(previous_members_[p], members[k]); n > 0) pairs.emplace_back(n, p, k);
  std::sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) {
    return std::get<0>(x) != std::get<0>(y) ? std::get<0>(x) > std::get<0>(y) : std::tie(std::get<1>(x), std::get<2>(x)) < std::tie(std::get<1>(y), std::get<2>(y));
  });
  std::vector<int> track_of(count, 0);
  std::vector<bool> previous_taken(previous_members_.size(), false);
  for (const auto& [n, p, k] : pairs) {
    if (previous_taken[p] || track_of[k] != 0) continue;
    previous_taken[p] = true;
    track_of[k] = last_tracks_[p];
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (track_of[k] == 0) {
      tracks_.push_back({static_cast<int>(tracks_.size()) + 1, {}});
      track_of[k] = tracks_.back().number;
    }
    tracks_[static_cast<std::size_t>(track_of[k] - 1)].points.push_back({frame, timestep, k, result.clusters[k]});
  }
  previous_members_ = std::move(members);
  last_tracks_ = std::move(track_of);
}

PowerLawFit fit_power_law(const std::string& quantity, const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> log_t, log_y;
  for (std::size_t i = 0; i < t.size() && i < y.size(); ++i)
    if (t[i] > 0 && y[i] > 0 && std::isfinite(y[i])) log_t.push_back(std::log(t[i])), log_y.push_back(std::log(y[i]));
  if (log_t.size() < 3)
    throw InputError(fmt::format("growth law of {}: {} points with t > 0, at least 3 are needed", quantity, log_t.size()));
  const analysis::LineFit line = analysis::fit_line(log_t, log_y);  // ln y = ln C + k ln t
  return {quantity, line.slope, line.slope_stderr, std::exp(line.intercept), line.points};
}

std::vector<PowerLawFit> fit_growth(const ClusterTrack& track, long long origin, double dt) {
  std::vector<double> t;
  std::vector<std::vector<double>> values(7);
  for (const TrackPoint& p : track.points) {
    t.push_back(static_cast<double>(p.timestep - origin) * dt);
    const Vec3& s = p.shape.semi_axes;
    const double size = std::cbrt(s.prod());
    const double row[7] = {s[0], s[1], s[2], size, p.shape.ellipsoid_surface, p.shape.ellipsoid_volume, p.shape.atomic_volume};
    for (int q = 0; q < 7; ++q) values[static_cast<std::size_t>(q)].push_back(row[q]);
  }
  static const char* kNames[7] = {"a_A", "b_A", "c_A", "L_A", "ellipsoid_surface_A2", "ellipsoid_volume_A3",
                                  "atomic_volume_A3"};
  std::vector<PowerLawFit> fits;
  for (int q = 0; q < 7; ++q) {
    const auto& y = values[static_cast<std::size_t>(q)];
    std::size_t usable = 0;
    for (std::size_t i = 0; i < t.size(); ++i) usable += t[i] > 0 && y[i] > 0;
    if (usable >= 3) fits.push_back(fit_power_law(kNames[q], t, y));
  }
  return fits;
}

std::vector<std::string> track_columns(bool time_in_ps) {
  return {"track", "frame", "timestep", time_in_ps ? "time_ps" : "elapsed_timesteps", "cluster", "size", "x_A", "y_A",
          "z_A", "a_A", "b_A", "c_A", "L_A", "ellipsoid_surface_A2", "ellipsoid_volume_A3", "atomic_volume_A3"};
}

std::vector<std::vector<double>> track_rows(const std::vector<ClusterTrack>& tracks, long long origin, double dt) {
  std::vector<std::vector<double>> rows;
  for (const ClusterTrack& t : tracks)
    for (const TrackPoint& p : t.points) {
      const Cluster& c = p.shape;
      rows.push_back({double(t.number), double(p.frame), double(p.timestep), double(p.timestep - origin) * dt,
                      double(p.cluster + 1), double(c.size), c.centre.x(), c.centre.y(), c.centre.z(), c.semi_axes[0],
                      c.semi_axes[1], c.semi_axes[2], std::cbrt(c.semi_axes.prod()), c.ellipsoid_surface,
                      c.ellipsoid_volume, c.atomic_volume});
    }
  return rows;
}

}  // namespace shockfield::analysis::atoms
