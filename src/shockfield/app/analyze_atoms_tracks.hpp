#pragma once
// The cluster-tracking part of `shockfield analyze atoms` (analysis/atoms/cluster_tracking): with
// --track, the clusters of --clusters followed through the frames (OUTPUT/tracks.csv, a column
// `track` in the dumps) and each track's growth laws y = C t^k (OUTPUT/growth.csv, printed).
#include <CLI/CLI.hpp>

#include <filesystem>

#include "shockfield/analysis/atoms/cluster_tracking.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::app {

struct TrackArgs {
  bool track = false;
  long long origin = 0;  ///< timestep from which growth time is counted (nucleation)
  double dt = 1.0;       ///< time per timestep (ps for an MD run); 1: time in timesteps
  bool dt_given = false;  ///< --timestep-size given: the growth time is in ps (tracks.csv's time_ps)
};

void add_track_options(CLI::App& cmd, TrackArgs& args);

class TrackOutput {
 public:
  /// InputError when --track is given without --clusters.
  TrackOutput(const TrackArgs& args, bool clusters_on);
  /// One frame's clusters; appends the column `track` (0: in no cluster) to the dump.
  void add(std::size_t frame, const analysis::atoms::AtomFrame& atoms, const analysis::atoms::ClusterResult& clusters,
           io::DumpFrame& dump);
  /// Writes tracks.csv and growth.csv (paths given by the caller) and prints the fits.
  void write(const std::filesystem::path& tracks_file, const std::filesystem::path& growth_file) const;

 private:
  TrackArgs args_;
  analysis::atoms::ClusterTracker tracker_;
};

}  // namespace shockfield::app
