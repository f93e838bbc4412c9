// Voids and phase-domain surfaces of a frame of atoms (atom_surfaces.hpp).
#include "shockfield/analysis/atoms/atom_surfaces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/rolling_ball.hpp"

namespace shockfield::analysis::atoms {
namespace {

// The atoms and, along periodic dimensions, their images within `margin` of the faces, so that
// a void across a periodic face is closed in the (non-periodic) division.
std::vector<std::array<double, 3>> with_images(const AtomFrame& frame, double margin) {
  std::vector<std::array<double, 3>> points;
  const geometry::Box& box = frame.box;
  geometry::require_orthogonal(box, "the void and domain surfaces (periodic images along x, y, z)");
  for (const Vec3& x0 : frame.positions) {
    Vec3 x = x0;
    for (int d = 0; d < 3; ++d)
      if (box.periodic(d)) x[d] -= box.length()[d] * std::floor((x[d] - box.lo[d]) / box.length()[d]);
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy)
        for (int sz = -1; sz <= 1; ++sz) {
          const int shift[3] = {sx, sy, sz};
          Vec3 image = x;
          bool keep = true;
          for (int d = 0; d < 3 && keep; ++d) {
            if (shift[d] == 0) continue;
            image[d] += shift[d] * box.length()[d];
            keep = box.periodic(d) && image[d] >= box.lo[d] - margin && image[d] < box.hi[d] + margin;
          }
          if (keep) points.push_back({image.x(), image.y(), image.z()});
        }
  }
  return points;
}

void append_surface(SurfaceSet& set, const geometry::TriangleSurface& s, std::int32_t offset) {
  for (const auto& t : s.triangles) set.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace

double equivalent_radius(double volume) { return std::cbrt(3.0 * std::max(volume, 0.0) / (4.0 * std::numbers::pi)); }

VoidResult find_voids(const AtomFrame& frame, const VoidSearch& search) {
  const geometry::Box& box = frame.box;
  double margin = search.margin.value_or(15.0);
  for (int d = 0; d < 3; ++d)
    if (box.periodic(d)) margin = std::min(margin, 0.5 * box.length()[d]);
  const auto division =
      geometry::delaunay_division<3>(with_images(frame, margin), fmt::format("the atoms of timestep {}", frame.timestep));
  // A void near a periodic face is found whole in several copies (it and its images): the copies
  // have the same centre once wrapped into the box; one is kept, with its centre wrapped.
  std::vector<geometry::Cavity> cavities;
  for (geometry::Cavity& c : geometry::rolling_ball_cavities(division, search.probe)) {
    Vec3 centre(c.centroid[0], c.centroid[1], c.centroid[2]);
    std::array<int, 3> image{0, 0, 0};
    box.wrap(centre, image);
    const bool copy = std::any_of(cavities.begin(), cavities.end(), [&](const geometry::Cavity& k) {
      return box.minimum_image(Vec3(k.centroid[0], k.centroid[1], k.centroid[2]) - centre).norm() < 1e-3;
    });
    if (copy) continue;
    c.centroid = {centre.x(), centre.y(), centre.z()};
    cavities.push_back(std::move(c));
  }
  double cavity_volume = 0;
  for (const geometry::Cavity& c : cavities) cavity_volume += c.surface.volume;
  const double omega = search.atomic_volume.value_or((box.volume() - cavity_volume) / static_cast<double>(frame.size()));
  VoidResult result;
  result.surfaces.points = division.points;
  for (const geometry::Cavity& c : cavities) {
    if (c.surface.volume < search.min_volume) continue;
    std::vector<char> on_surface(division.points.size(), 0);
    for (const auto& t : c.surface.triangles)
      for (std::int32_t v : t) on_surface[static_cast<std::size_t>(v)] = 1;
    Void v;
    v.cells = c.cells;
    v.volume = c.surface.volume;
    v.area = c.surface.area;
    v.missing_volume = c.surface.volume - omega * c.vertex_solid_angle / (4.0 * std::numbers::pi);
    v.centre = Vec3(c.centroid[0], c.centroid[1], c.centroid[2]);
    v.surface_atoms = static_cast<std::size_t>(std::count(on_surface.begin(), on_surface.end(), 1));
    v.euler_characteristic = c.surface.euler_characteristic;
    v.manifold = c.surface.manifold;
    result.voids.push_back(v);
    append_surface(result.surfaces, c.surface, 0);
  }
  return result;
}

DomainResult domain_surfaces(const AtomFrame& frame, const ClusterResult& clusters, const DomainSurfaces& options) {
  const geometry::Box& box = frame.box;
  geometry::require_orthogonal(box, "the domain surfaces");
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
  DomainResult result;
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k].size() < options.min_atoms) continue;
    const std::string name = fmt::format("the atoms of domain {} at timestep {}", k + 1, frame.timestep);
    std::optional<geometry::DelaunayDivision<3>> division;
    try {
      division.emplace(geometry::delaunay_division<3>(members[k], name));
    } catch (const InputError& e) {  // a flat domain (one atomic plane: a twin boundary) has no volume
      result.flat.emplace_back(e.what());
      continue;
    }
    const geometry::EnclosedSolid solid = [&] {
      try {
        return options.packing ? geometry::packing_sculpting_solid(*division, options.probe)
                               : geometry::rolling_ball_solid(*division, options.probe);
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", name, e.what()));
      }
    }();
    const geometry::TriangleSurface& s = solid.surface;
    // The atoms' own (Voronoi) volume: the polyhedron through the outer atoms' centres holds the
    // share ω_i/4π of atom i's cell, so Σ_i Ω (1 − ω_i/4π) of the atoms' cells lies outside it.
    const double n = static_cast<double>(members[k].size());
    Domain d;
    d.cluster = k;
    d.atoms = members[k].size();
    d.volume = s.volume;
    d.area = s.area;
    d.atoms_volume = s.volume + omega * (n - solid.vertex_solid_angle / (4.0 * std::numbers::pi));
    d.centre = clusters.clusters[k].centre;
    d.euler_characteristic = s.euler_characteristic;
    d.manifold = s.manifold;
    result.domains.push_back(d);
    const auto offset = static_cast<std::int32_t>(result.surfaces.points.size());
    result.surfaces.points.insert(result.surfaces.points.end(), s.points.begin(), s.points.end());
    append_surface(result.surfaces, s, offset);
  }
  return result;
}

}  // namespace shockfield::analysis::atoms
