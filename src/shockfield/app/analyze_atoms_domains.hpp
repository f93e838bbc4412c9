#pragma once
// The phase domains of `shockfield analyze atoms --domains R` (Xu et al. (2015) §3.2.3, surfaces of
// phase domains from the structure analysis): each cluster of --clusters/--cluster-select (e.g. the
// bcc or hcp atoms by CNA) made whole across periodic faces, its Delaunay division and the surface
// a ball of radius R rolled from outside touches, or the packing-sculpting surface to depth R
// (geometry/rolling_ball), with the volume and
// area per domain and frame (OUTPUT/domains.csv), the surfaces (OUTPUT/domains_<timestep>.vtp)
// and a plot of volume and area against time (OUTPUT/domains.png). The voids of --voids are the
// model (analyze_atoms_voids).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/defect_clusters.hpp"
#include "shockfield/app/analyze_atoms_voids.hpp"

namespace shockfield::app {

struct DomainArgs {
  std::optional<double> probe;  ///< Å: ball radius or sculpting depth
  std::string surface = "rolling";  ///< rolling (ball) or packing (packing-sculpting)
  std::size_t min_atoms = 4;    ///< smaller clusters have no surface
};

void add_domain_options(CLI::App& cmd, DomainArgs& args);

class DomainOutput {
 public:
  /// `add_file` registers an output file (written as .partial until every input is analysed).
  /// InputError when --domains is given without the clusters it needs.
  DomainOutput(const DomainArgs& args, bool clusters_on,
               std::function<std::filesystem::path(const std::filesystem::path&)> add_file);
  bool on() const { return args_.probe.has_value(); }
  void add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame,
           const analysis::atoms::ClusterResult& clusters);
  void close() { files_.close(); }
  void plot(const std::filesystem::path& folder) const {
    if (on()) files_.plot(folder);
  }
  std::size_t domains() const { return domains_; }
  std::size_t flat() const { return flat_; }

 private:
  DomainArgs args_;
  SurfaceSeries files_;
  std::size_t domains_ = 0, flat_ = 0;
};

}  // namespace shockfield::app
