#include "shockfield/app/analyze_atoms_domains.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/rolling_ball.hpp"

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
  files_ = SurfaceSeries("domains",
                         "frame,timestep,domain,atoms,volume,area,equivalent_radius,atoms_volume,atoms_radius,x,y,z,"
                         "euler_characteristic,manifold\n",
                         add_file);
}

void DomainOutput::add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame,
                       const analysis::atoms::ClusterResult& clusters) {
  const geometry::Box& box = frame.box;
  const double omega = box.volume() / static_cast<double>(frame.size());
  std::vector<std::vector<std::array<double, 3>>> members(clusters.clusters.size());
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const int k = clusters.cluster_of[i];
    if (k < 0) continue;
    // Whole across periodic faces: each atom at its image nearest the cluster's centre.
    const Vec3& c = clusters.clusters[static_cast<std::size_t>(k)].centre;
    const Vec3 x = c + box.minimum_image(frame.positions[i] - c);
    members[static_cast<std::size_t>(k)].push_back({x.x(), x.y(), x.z()});
  }
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::int32_t, 3>> triangles;
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k].size() < args_.min_atoms) continue;
    const std::string name = fmt::format("the atoms of domain {} at timestep {}", k + 1, frame.timestep);
    std::optional<geometry::DelaunayDivision<3>> division;
    try {
      division.emplace(geometry::delaunay_division<3>(members[k], name));
    } catch (const InputError& e) {  // a flat domain (one atomic plane: a twin boundary) has no volume
      std::fprintf(stderr, "warning: no surface for %s\n", e.what());
      ++flat_;
      continue;
    }
    const geometry::EnclosedSolid solid = [&] {
      try {
        return args_.surface == "packing" ? geometry::packing_sculpting_solid(*division, *args_.probe)
                                          : geometry::rolling_ball_solid(*division, *args_.probe);
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", name, e.what()));
      }
    }();
    const geometry::TriangleSurface& s = solid.surface;
    // The atoms' own (Voronoi) volume: the polyhedron through the outer atoms' centres holds the
    // share ω_i/4π of atom i's cell, so Σ_i Ω (1 − ω_i/4π) of the atoms' cells lies outside it.
    const double n = static_cast<double>(members[k].size());
    const double atoms_volume = s.volume + omega * (n - solid.vertex_solid_angle / (4.0 * std::numbers::pi));
    const Vec3& c = clusters.clusters[k].centre;
    files_.csv() << fmt::format("{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{}\n",
                        frame_index, frame.timestep, k + 1, members[k].size(), s.volume, s.area,
                        equivalent_radius(s.volume), atoms_volume, equivalent_radius(atoms_volume), c.x(), c.y(),
                        c.z(), s.euler_characteristic, s.manifold ? 1 : 0);
    const auto offset = static_cast<std::int32_t>(points.size());
    points.insert(points.end(), s.points.begin(), s.points.end());
    for (const auto& t : s.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    ++domains_;
  }
  files_.end_frame(frame.timestep, points, triangles);
}

}  // namespace shockfield::app
