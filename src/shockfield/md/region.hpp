#pragma once
// Geometric regions and named groups, after the LAMMPS `region`, `delete_atoms region` and
// `group ID region` commands. Coordinates are box units (Å) — LAMMPS `units box`; regions do not
// wrap across periodic faces (as in LAMMPS).
//   block     lo ≤ x ≤ hi in every dimension (RegBlock::inside; ±inf leaves a side open)
//   sphere    |x − center| ≤ radius (RegSphere::inside)
//   cylinder  distance from the axis line ≤ radius and lo ≤ x_axis ≤ hi (RegCylinder::inside)
// side = out selects the complement (Region::match with `side out`).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/types.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

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

/// Removes the owned atoms the region matches (LAMMPS `delete_atoms region`); returns how many.
std::size_t delete_atoms(const Region& region, Atoms& atoms);

/// Named groups as bits of Atoms::mask (LAMMPS `group`): bit 0 is "all", at most 32 groups.
class GroupTable {
 public:
  GroupTable() : names_{"all"} {}
  /// The bit of a group, creating it when new; InputError when the 32 bits are used up.
  std::uint32_t bit(const std::string& name);
  /// The bit of an existing group; InputError naming the known groups otherwise.
  std::uint32_t find(const std::string& name) const;
  bool has(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
};

/// Adds the atoms the region matches to the group (LAMMPS `group ID region`); returns how many
/// atoms the group has afterwards.
std::size_t add_to_group(std::uint32_t bit, const Region& region, Atoms& atoms);
/// Adds the atoms of the given 0-based types to the group (LAMMPS `group ID type ...`).
std::size_t add_to_group(std::uint32_t bit, const std::vector<int>& types, Atoms& atoms);

}  // namespace shockfield::md
