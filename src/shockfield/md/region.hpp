#pragma once
// Regions (geometry/region.hpp, LAMMPS `region`) applied to atoms, and named groups, after the
// LAMMPS `delete_atoms region` and `group ID region` commands. Coordinates are box units (Å) —
// LAMMPS `units box`.
#include <cstdint>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/geometry/region.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

using geometry::Region;
using geometry::region_from_config;

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
