#pragma once
// LAMMPS data files, atom style atomic (`read_data` / `write_data`), orthogonal or triclinic
// boxes.
//
//   <title line>
//   N atoms
//   M atom types
//   xlo xhi / ylo yhi / zlo zhi
//   xy xz yz                    tilt factors (optional; a restricted triclinic box, LAMMPS's limits)
//   Masses                      type mass [# element]
//   Atoms # atomic              id type x y z [ix iy iz]
//   Velocities                  id vx vy vz      (optional)
//
// `#` starts a comment anywhere; blank lines are ignored. "Pair Coeffs" / "PairIJ Coeffs"
// sections are skipped (the force field comes from the case file); other sections and bonds
// are rejected. As in LAMMPS read_data, atoms outside a periodic box are remapped
// into it (image flags updated) and atoms outside a non-periodic box are an error, where a
// shrink-wrapped dimension first grows by LAMMPS's margin, 1e-4 × its length on each side
// (Domain::set_initial_box). Every error names the file, the line and what was expected.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::io {

struct DataFile {
  std::string title;
  geometry::Box box;
  /// Owned atoms in file order; mass per type (0 where the Masses section did not give one),
  /// type_names from a "# Cu" comment after the mass, else "".
  md::Atoms atoms;
  bool has_velocities = false;
};

/// Reads a data file; `boundary` plays the role of the LAMMPS `boundary` command before read_data.
DataFile read_data(const std::filesystem::path& file,
                   const std::array<geometry::Boundary, 3>& boundary = {
                       geometry::Boundary::periodic, geometry::Boundary::periodic,
                       geometry::Boundary::periodic});

struct DataWriteOptions {
  std::string title = "LAMMPS data file written by shockfield";
  bool velocities = true;   ///< write the Velocities section
  bool image_flags = true;  ///< write ix iy iz after the positions
  /// Pad of shrink-wrapped faces (geometry::shrink_margin of the box the run was created with);
  /// default 1e-4 × the lengths of the box given.
  std::optional<Vec3> shrink_margin = std::nullopt;
};

/// Writes the owned atoms of `atoms` as a LAMMPS data file (atom style atomic), positions and
/// velocities to full precision (they read back bit-identical). As LAMMPS write_data does, the
/// positions are first wrapped into the periodic dimensions (image flags updated) and the
/// shrink-wrapped dimensions reset to the atoms (geometry::shrink_wrap), so that every atom lies in
/// the written box and LAMMPS read_data or read_data() above assigns them all; `box` and `atoms`
/// themselves are not changed. The file is replaced atomically (a temporary file and a rename):
/// a reader never sees half of it.
void write_data(const std::filesystem::path& file, const geometry::Box& box, const md::Atoms& atoms,
                const DataWriteOptions& options = {});

}  // namespace shockfield::io
