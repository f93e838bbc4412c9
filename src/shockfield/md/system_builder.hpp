#pragma once
// Builds the atomic system of an MD case from its [system] table (keys: docs/md-system.md):
// a crystal (`[system.lattice]`, LAMMPS lattice + create_atoms) or a LAMMPS data file
// (`data_file`, LAMMPS read_data), then `[[system.delete]]` regions (delete_atoms region) and
// `[[system.group]]` definitions (group ID region / group ID type). Checks that every atom is
// inside a non-periodic box and that no two atoms are closer than `min_distance`.
#include <optional>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/region.hpp"

namespace shockfield::md {

struct BuiltSystem {
  geometry::Box box;
  Atoms atoms;        ///< owned atoms, ids 1..N (lattice) or as in the data file; masks set
  GroupTable groups;  ///< "all" plus the [[system.group]] names, bits as in atoms.mask
  /// The data file's Masses per type (0 where it gives none; empty for a lattice). They are not
  /// in atoms.mass: as in LAMMPS, where pair_coeff sets the potential file's masses after
  /// read_data, the potential's mass wins and the data file's is the fallback (md/run_case.cpp).
  std::vector<double> file_masses;
  /// `--check` of a crystal larger than a few cells (build_system's `check`): `atoms` holds only
  /// the crystal's first few cells (for the types, masses and the overlap check) and this, the
  /// atoms per type of the whole crystal after [[system.delete]], counted without storing them.
  std::vector<std::size_t> counted_types;

  /// The system's atoms: atoms.nlocal, or the count of the whole crystal under --check.
  std::size_t atom_count() const;
  /// Σ mass per atom (amu), of the whole crystal under --check.
  double total_mass() const;
};

/// Reads and validates the [system] table and builds the system; InputError naming file, key and
/// line (or the data file and its line) on any problem. `data_file` is relative to the folder of
/// the case file (Config::file()).
/// Types without a mass keep mass 0 (to be taken from the potential). Derived values (atom count,
/// atoms deleted and per group, box lengths) are recorded with Config::derive.
/// `check` (shockfield run --check): a crystal of more than 3 cells along an axis is counted, not
/// built (BuiltSystem::counted_types), so that --check of 10^9 atoms takes seconds and no memory.
BuiltSystem build_system(const Config& system, bool check = false);

/// The first pair of atoms (periodic images included) closer than `min_distance`, described with
/// both ids and their distance; nullopt when there is none.
std::optional<std::string> find_overlap(const geometry::Box& box, const Atoms& atoms, double min_distance);

}  // namespace shockfield::md
