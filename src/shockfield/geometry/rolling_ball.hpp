#pragma once
// The rolling-ball surface of a 3D point set (Xu et al. 2015 §3.2.3, "Rolling-ball method for
// finding interfaces"): the triangles whose three points a ball of radius r, rolled over the points
// from outside, touches at once. Computed here from the Delaunay division rather than by the paper's
// pivoting (pivoting_ball.hpp, on MS1/MS3/CS1): an empty ball of radius r can sit at the
// circumcentre of a tetrahedron whose circumradius exceeds r, and can move between two neighbouring
// tetrahedra along the Voronoi edge of their common face when every point of that edge stays at
// least r from the face's vertices (the smallest distance on the edge is the face's circumradius
// when the edge crosses the face's plane, else the smaller circumradius at its ends). The balls
// reachable from infinity form the exterior E; the surface is every face across which a ball in E
// is stopped, oriented with its normal towards E — where the ball stops on a face it touches the
// face's three vertices, as the paper's rolling ball does. As the boundary of a set of cells (a face
// blocked between two cells of E counts once from each side), the surface is always closed.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/geometry/delaunay.hpp"

namespace shockfield::geometry {

struct TriangleSurface {
  std::vector<std::array<double, 3>> points;  ///< the division's points (indices below refer here)
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< normals (right-hand rule) point outwards
  double area = 0.0;
  double volume = 0.0;  ///< enclosed volume (divergence theorem over the oriented triangles)
  std::int64_t euler_characteristic = 0;  ///< V − E + F of the triangles
  /// Every edge on exactly two triangles, once in each direction (edge-manifold, consistently oriented).
  bool manifold = false;
};

/// Fills area, volume, euler_characteristic and manifold from the points and triangles.
void measure_surface(TriangleSurface& s);

/// A cavity: a set of tetrahedra where a ball of the radius can sit and move, not reachable from
/// outside — a void inside the point set (a vacancy cluster, a void in a crystal). Its surface
/// is where the ball is stopped (the triangles of the atoms it touches), normals out of the
/// cavity, so `surface.volume` is the cavity's volume (the polyhedron through the centres of the
/// atoms around it, equal to `cell_volume`).
struct Cavity {
  TriangleSurface surface;
  std::size_t cells = 0;
  double cell_volume = 0.0;                  ///< sum of the cavity's tetrahedra
  std::array<double, 3> centroid{0, 0, 0};  ///< volume-weighted
  /// Σ over the cavity's tetrahedra of the solid angles at their vertices (sr): ω_i/4π of the
  /// space around point i is cavity, so Σ_i Ω_i ω_i/4π is the share of the surrounding points'
  /// own (Voronoi) volumes Ω_i inside the cavity's polyhedron.
  double vertex_solid_angle = 0.0;
};

/// Every cavity of a ball of radius `radius`, largest first: the connected sets (through faces the
/// ball passes) of tetrahedra with circumradius > radius that the ball cannot reach from outside.
/// InputError for a radius that is not positive and finite. A cavity open to the outside (through
/// the convex hull) is part of the exterior and not listed.
std::vector<Cavity> rolling_ball_cavities(const DelaunayDivision<3>& d, double radius);

/// The surface touched by a ball of radius `radius` rolled from outside. Throws InputError for a
/// radius that is not positive and finite, and when the ball passes everywhere between the points
/// (no surface: the radius is too small for the point spacing).
TriangleSurface rolling_ball_surface(const DelaunayDivision<3>& d, double radius);

/// A surface from outside with what it encloses: the tetrahedra left (rolling ball: those the
/// ball cannot reach from outside, cavities included; sculpting: those not carved).
struct EnclosedSolid {
  TriangleSurface surface;
  /// Σ over the enclosed tetrahedra of the solid angles at their vertices (sr): ω_i/4π of the space
  /// around point i is enclosed (1 inside, about 1/2 on a flat part of the surface).
  double vertex_solid_angle = 0.0;
};
/// rolling_ball_surface with what it encloses.
EnclosedSolid rolling_ball_solid(const DelaunayDivision<3>& d, double radius);

/// The packing-sculpting surface (Xu et al. 2015 §3.2.3): packing is the convex hull (here the
/// boundary of the whole Delaunay division); sculpting removes, from the outside in, each
/// tetrahedron behind a surface face ABC whose sphere through A, B, C, shrinking from infinite
/// radius on the outer side, meets the tetrahedron's fourth point before its radius falls to the
/// depth s or below (BallPassage::grows in rolling_ball.cpp has the rule). The surface is the
/// boundary of the tetrahedra left, normals outwards, so `volume` is their total volume. InputError
/// for a depth that is not positive and finite, when sculpting removes every tetrahedron, and when
/// what is left is not edge-manifold (the depth is below the spacing somewhere).
TriangleSurface packing_sculpting_surface(const DelaunayDivision<3>& d, double depth);
/// packing_sculpting_surface with what it encloses.
EnclosedSolid packing_sculpting_solid(const DelaunayDivision<3>& d, double depth);

}  // namespace shockfield::geometry
