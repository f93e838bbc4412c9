#pragma once
// Geometric regions after the LAMMPS `region` command, shared by the methods that select points by
// shape (md/region.hpp: `delete`, `group`; pd/regions.hpp: loading regions). Coordinates are those of
// the method (MD box units in Å; PD reference positions in m); regions do not wrap across
// periodic faces (as in LAMMPS).
//   block     lo ≤ x ≤ hi in every dimension (RegBlock::inside; ±inf leaves a side open)
//   sphere    |x − center| ≤ radius (RegSphere::inside)
//   cylinder  distance from the axis line ≤ radius and lo ≤ x_axis ≤ hi (RegCylinder::inside)
// side = out selects the complement (Region::match with `side out`).
#include <limits>

#include "shockfield/core/config.hpp"
#include "shockfield/core/types.hpp"

namespace shockfield::geometry {

struct Region {
  enum class Shape { block, sphere, cylinder };
  Shape shape = Shape::block;
  Vec3 lo = Vec3::Constant(-std::numeric_limits<double>::infinity());  ///< block corners
  Vec3 hi = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 center = Vec3::Zero();  ///< sphere centre; cylinder: a point on its axis
  double radius = 0.0;
  int axis = 2;                                                         ///< cylinder axis (0 x, 1 y, 2 z)
  double axial_lo = -std::numeric_limits<double>::infinity();           ///< cylinder extent on its axis
  double axial_hi = std::numeric_limits<double>::infinity();
  bool side_in = true;

  bool inside(const Vec3& x) const;
  bool match(const Vec3& x) const { return inside(x) == side_in; }
};

/// Reads a region from a case-file table:
///   shape = "block" | "sphere" | "cylinder", side = "in" (default) | "out"
///   block:    xlo, xhi, ylo, yhi, zlo, zhi   (each optional; an absent bound is open, INF)
///   sphere:   center = [x, y, z], radius
///   cylinder: axis = "x" | "y" | "z", center = [c1, c2] (the other two coordinates, in x, y, z
///             order), radius, lo / hi along the axis (default ±inf)
Region region_from_config(const Config& table);

}  // namespace shockfield::geometry
