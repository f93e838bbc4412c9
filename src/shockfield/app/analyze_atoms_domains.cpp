#include "shockfield/app/analyze_atoms_domains.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "shockfield/analysis/atoms/atom_surfaces.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {

void add_domain_options(CLI::App& cmd, DomainArgs& a) {
  cmd.add_option("--domains", a.probe,
                 "Phase domains: the surface of each cluster of --clusters/--cluster-select (e.g. --cluster-select "
                 "acna:bcc) touched by a ball of this radius (Å; above the domain's nearest-neighbour distance, e.g. "
                 "a) rolled from outside; writes OUTPUT/domains.csv (per frame and domain: atoms, volume and area of "
                 "the surface through the centres of its outer atoms, the atoms' own volume, centre), "
                 "OUTPUT/domains_<timestep>.vtp and OUTPUT/domains.png (volume and area against time)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--domains-surface", a.surface,
                 "The domains' surfaces: rolling (a ball of radius R rolled from outside) or packing (the "
                 "packing-sculpting surface of Xu et al. 2015 to depth R: the convex hull carved from outside; a "
                 "depth that leaves no closed manifold is an error)")
      ->capture_default_str()
      ->check(CLI::IsMember({"rolling", "packing"}));
  cmd.add_option("--domains-min-atoms", a.min_atoms, "Clusters with fewer atoms get no surface (at least 4)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{4}, std::size_t{1} << 40));
}

DomainOutput::DomainOutput(const DomainArgs& args, bool clusters_on,
                           std::function<std::filesystem::path(const std::filesystem::path&)> add_file)
    : args_(args) {
  if (!on()) return;
  if (!clusters_on)
    throw InputError("--domains needs the clusters that form the domains: add --clusters CUTOFF and "
                     "--cluster-select (e.g. --clusters 3 --cluster-select acna:bcc)");
  files_ = SurfaceSeries("domains", analysis::atoms::csv_header(analysis::atoms::domain_columns()), add_file);
}

void DomainOutput::add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame,
                       const analysis::atoms::ClusterResult& clusters) {
  namespace aa = analysis::atoms;
  const aa::DomainResult r =
      aa::domain_surfaces(frame, clusters, aa::DomainSurfaces{*args_.probe, args_.surface == "packing", args_.min_atoms});
  for (const std::string& why : r.flat) std::fprintf(stderr, "warning: no surface for %s\n", why.c_str());
  for (const aa::Domain& d : r.domains)
    files_.csv() << fmt::format("{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{}\n",
                                frame_index, frame.timestep, d.cluster + 1, d.atoms, d.volume, d.area,
                                aa::equivalent_radius(d.volume), d.atoms_volume, aa::equivalent_radius(d.atoms_volume),
                                d.centre.x(), d.centre.y(), d.centre.z(), d.euler_characteristic, d.manifold ? 1 : 0);
  domains_ += r.domains.size();
  flat_ += r.flat.size();
  files_.end_frame(frame.timestep, r.surfaces.points, r.surfaces.triangles);
}

}  // namespace shockfield::app
