#pragma once
// Defect clusters followed through a series of frames, and their growth laws — Xu et al. (2015)
// §4.4.2, Figs 71–72: the hcp domains of shocked iron grow as L ~ t^0.5 (the paper's fit 0.465),
// A ~ t^1.0, V ~ t^1.5.
//
// Tracking: a cluster of frame n continues the track whose cluster in frame n − 1 shares the most
// atom ids with it; each track continues by at most one cluster (pairs taken in decreasing order
// of shared atoms, ties by the lower track and cluster numbers), the other clusters start new
// tracks. A domain that splits keeps its track in its larger share; two that merge continue the
// one that gives the merged domain the most atoms. A track ends when no cluster of a frame shares
// an atom with it.
//
// Growth laws: for each track, y = C t^k fitted by least squares on (ln t, ln y) with the
// standard error of k from the residuals (analysis::fit_line), for the semi-axes a ≥ b ≥ c, the size
// L = (abc)^{1/3}, the ellipsoid surface A and volume V, and the atomic volume; t = (timestep −
// origin) · dt, points with t ≤ 0 left out (the origin is the domain's nucleation step).
#include <cstdint>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/defect_clusters.hpp"

namespace shockfield::analysis::atoms {

struct TrackPoint {
  std::size_t frame = 0;
  long long timestep = 0;
  std::size_t cluster = 0;  ///< 0-based index in that frame's ClusterResult
  Cluster shape;
};

struct ClusterTrack {
  int number = 0;                  ///< 1, 2, ... in order of appearance
  std::vector<TrackPoint> points;  ///< one per frame it was seen in, in order
};

class ClusterTracker {
 public:
  /// Adds one frame's clusters (`ids` the frame's atom ids, 1..N when empty).
  void add(std::size_t frame, long long timestep, const std::vector<std::int64_t>& ids, const ClusterResult& clusters);
  const std::vector<ClusterTrack>& tracks() const { return tracks_; }
  /// The track each cluster of the last frame added belongs to (track numbers).
  const std::vector<int>& last_tracks() const { return last_tracks_; }

 private:
  std::vector<ClusterTrack> tracks_;
  std::vector<std::vector<std::int64_t>> previous_members_;  ///< per cluster of the last frame, sorted ids
  std::vector<int> last_tracks_;
};

struct PowerLawFit {
  std::string quantity;
  double exponent = 0, exponent_stderr = 0, prefactor = 0;
  int points = 0;
};

/// tracks.csv's columns (docs/conventions.md: units in the names, those of clusters.csv): track,
/// frame, timestep, the growth time (timestep − origin) · dt as `time_ps` when dt is an MD time step
/// in ps, else as `elapsed_timesteps` (dt = 1), cluster (1, 2, ...), size, centre x_A, y_A, z_A,
/// semi-axes a_A, b_A, c_A, L_A = (abc)^{1/3}, ellipsoid_surface_A2, ellipsoid_volume_A3,
/// atomic_volume_A3.
std::vector<std::string> track_columns(bool time_in_ps);
/// Their values: one row per track and frame it was seen in, tracks in order.
std::vector<std::vector<double>> track_rows(const std::vector<ClusterTrack>& tracks, long long origin, double dt);

/// y = C t^k for a, b, c, L, A, V and the atomic volume of one track, each named as its column
/// of tracks.csv (a_A, ..., ellipsoid_surface_A2, ellipsoid_volume_A3, atomic_volume_A3) (quantities with a
/// non-positive value are left out). Fewer than 3 points with t > 0: no fits.
std::vector<PowerLawFit> fit_growth(const ClusterTrack& track, long long origin, double dt);

/// One fit, y = C t^k over the points with t > 0 and y > 0; InputError with fewer than 3 of them.
PowerLawFit fit_power_law(const std::string& quantity, const std::vector<double>& t, const std::vector<double>& y);

}  // namespace shockfield::analysis::atoms
