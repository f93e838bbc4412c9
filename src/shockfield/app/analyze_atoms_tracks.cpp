#include "shockfield/app/analyze_atoms_tracks.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "shockfield/core/error.hpp"

namespace shockfield::app {

namespace aa = shockfield::analysis::atoms;

void add_track_options(CLI::App& cmd, TrackArgs& a) {
  cmd.add_flag("--track", a.track,
               "Follow the clusters of --clusters through the frames (a cluster continues the track of the previous "
               "frame's cluster it shares most atom ids with) and fit each track's growth laws y = C t^k for the "
               "semi-axes a, b, c, L = (abc)^(1/3), area A, volume V and atomic volume (Xu et al. (2015) Fig 72); "
               "writes OUTPUT/tracks.csv, OUTPUT/growth.csv and the dump column track");
  cmd.add_option("--growth-origin", a.origin, "Timestep from which the growth time t is counted (nucleation); points with t <= 0 are left out")
      ->capture_default_str();
  cmd.add_option_function<double>(
         "--timestep-size", [&a](double dt) { a.dt = dt, a.dt_given = true; },
         "The MD time step in ps: t in ps (tracks.csv's column time_ps); without it t is in timesteps "
         "(elapsed_timesteps)")
      ->check(CLI::PositiveNumber);
}

TrackOutput::TrackOutput(const TrackArgs& args, bool clusters_on) : args_(args) {
  if (!clusters_on) throw InputError("--track needs --clusters and --cluster-select (the clusters it follows)");
}

void TrackOutput::add(std::size_t frame, const aa::AtomFrame& atoms, const aa::ClusterResult& clusters, io::DumpFrame& dump) {
  tracker_.add(frame, atoms.timestep, atoms.ids, clusters);
  if (atoms.size() == 0) return;
  std::vector<double> track(atoms.size(), 0.0);
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (clusters.cluster_of[i] >= 0) track[i] = tracker_.last_tracks()[static_cast<std::size_t>(clusters.cluster_of[i])];
  dump.set_column("track", std::move(track));
}

void TrackOutput::write(const std::filesystem::path& tracks_file, const std::filesystem::path& growth_file) const {
  io::CheckedOutput tracks(tracks_file);
  std::string header;
  for (const std::string& c : aa::track_columns(args_.dt_given)) header += (header.empty() ? "" : ",") + c;
  tracks.write(header + "\n");
  for (const std::vector<double>& row : aa::track_rows(tracker_.tracks(), args_.origin, args_.dt)) {
    std::string line;
    for (std::size_t k = 0; k < row.size(); ++k) {
      const bool integer = k <= 2 || k == 4 || k == 5;  // track, frame, timestep, cluster, size
      line += (k == 0 ? "" : ",") + (integer ? fmt::format("{}", static_cast<long long>(row[k])) : fmt::format("{:.10g}", row[k]));
    }
    tracks.write(line + "\n");
  }
  tracks.close();
  io::CheckedOutput growth(growth_file);
  growth.write("track,quantity,exponent,exponent_stderr,prefactor,points\n");
  for (const aa::ClusterTrack& t : tracker_.tracks()) {
    const auto fits = aa::fit_growth(t, args_.origin, args_.dt);
    if (fits.empty()) continue;
    std::string line = fmt::format("track {} ({} frames, {} atoms at the end):", t.number, t.points.size(), t.points.back().shape.size);
    for (const aa::PowerLawFit& f : fits) {
      growth << fmt::format("{},{},{:.6g},{:.3g},{:.6g},{}\n", t.number, f.quantity, f.exponent, f.exponent_stderr, f.prefactor, f.points);
      if (f.quantity != "atomic_volume") line += fmt::format(" {} ~ t^{:.3f}±{:.3f}", f.quantity, f.exponent, f.exponent_stderr);
    }
    std::printf("%s\n", line.c_str());
  }
  growth.close();
}

}  // namespace shockfield::app
