#pragma once
// Point sets read from a file for the geometry commands: CSV/text (one point per line, values
// separated by commas or blanks, `#` comments; an optional header line naming columns — then x,
// y (and z) are taken by name, else the first N columns), extended/plain XYZ (count line, comment
// line, then "species x y z ..."), or a LAMMPS text dump (positions of one frame). Every failure
// is an InputError naming the file and line. Only a dump can name the unit of its coordinates (its
// `ITEM: UNITS` style, core/unit_names' lammps_length_unit); CSV and XYZ files name none.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::geometry {

/// The points of a file and what the file says of their unit.
template <int N>
struct PointSet {
  std::vector<std::array<double, N>> points;
  std::string length_unit;   ///< the unit the file names ("A" for ITEM: UNITS metal), "" when it names none
  bool lammps_dump = false;  ///< read from a LAMMPS dump (whose default, without ITEM: UNITS, is Å: metal units)
};

/// Reads N-dimensional points; `frame` selects the frame of a LAMMPS dump (0-based; −1 = last).
/// A 2D read of a 3D file takes x and y.
template <int N>
PointSet<N> read_points(const std::filesystem::path& file, int frame = 0);

}  // namespace shockfield::geometry
