#pragma once
// Surfaces in atoms (Xu et al. (2015) §3.2.3, rolling-ball and packing-sculpting surfaces;
// geometry/rolling_ball): the voids of `shockfield analyze atoms --voids R` — the cavities of the
// atoms' Delaunay division for a ball of radius R, regions the ball moves in without reaching the
// outside — and the phase domains of `--domains R` — each cluster of the structure analysis made
// whole across periodic faces, with the surface a ball of radius R rolled from outside touches (or
// the packing-sculpting surface to depth R). One frame in, the objects' volumes, areas and centres
// and their surfaces out; the command line writes them (app/analyze_atoms_voids,
// analyze_atoms_domains) and shockfield.analysis returns them.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/defect_clusters.hpp"

namespace shockfield::analysis::atoms {

/// The radius of the sphere of this volume (0 for a negative volume).
double equivalent_radius(double volume);

/// Triangles on a list of points (indices into `points`), normals out of the objects.
struct SurfaceSet {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

struct Void {
  std::size_t cells = 0;          ///< tetrahedra of the cavity
  double volume = 0;              ///< Å³, the polyhedron through the centres of the atoms around it
  double area = 0;                ///< Å², its surface
  double missing_volume = 0;      ///< Å³, the polyhedron less the surface atoms' own cells' share in it
  Vec3 centre = Vec3::Zero();     ///< Å, volume-weighted, wrapped into the box
  std::size_t surface_atoms = 0;  ///< points on its surface
  std::int64_t euler_characteristic = 0;
  bool manifold = false;
};

struct VoidSearch {
  double probe = 0;                     ///< Å, the ball's radius
  std::optional<double> atomic_volume;  ///< Å³; default (box volume − voids) / atoms
  std::optional<double> margin;         ///< Å of periodic images around the box; default 15, at most half the box
  double min_volume = 0;                ///< Å³; smaller voids are left out
};

struct VoidResult {
  std::vector<Void> voids;  ///< largest first
  SurfaceSet surfaces;      ///< every void's surface; the points are the atoms and their images
};

/// The voids of a frame (InputError from the Delaunay division or the ball's radius).
VoidResult find_voids(const AtomFrame& frame, const VoidSearch& search);

struct Domain {
  std::size_t cluster = 0;    ///< 0-based, as ClusterResult::clusters
  std::size_t atoms = 0;
  double volume = 0;          ///< Å³, enclosed by the surface through the outer atoms' centres
  double area = 0;            ///< Å²
  double atoms_volume = 0;    ///< Å³, the atoms' own (Voronoi) volume, box volume / atoms each
  Vec3 centre = Vec3::Zero();  ///< the cluster's centre
  std::int64_t euler_characteristic = 0;
  bool manifold = false;
};

struct DomainSurfaces {
  double probe = 0;            ///< Å: ball radius or sculpting depth
  bool packing = false;        ///< packing-sculpting instead of the rolling ball
  std::size_t min_atoms = 4;   ///< smaller clusters have no surface
};

struct DomainResult {
  std::vector<Domain> domains;    ///< in cluster order
  SurfaceSet surfaces;
  std::vector<std::string> flat;  ///< why each flat cluster (one atomic plane) has no surface
};

/// The surfaces of the clusters of a frame (InputError, naming the domain, when a surface fails).
DomainResult domain_surfaces(const AtomFrame& frame, const ClusterResult& clusters, const DomainSurfaces& options);

}  // namespace shockfield::analysis::atoms
