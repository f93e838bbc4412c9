#pragma once
// Point sets read from a file for the geometry commands: CSV/text (one point per line, values
// separated by commas or blanks, `#` comments; an optional header line naming columns — then x,
// y (and z) are taken by name, else the first N columns), extended/plain XYZ (count line, comment
// line, then "species x y z ..."), or a LAMMPS text dump (positions of one frame). Every failure
// is an InputError naming the file and line.
#include <array>
#include <filesystem>
#include <vector>

namespace shockfield::geometry {

/// Reads N-dimensional points; `frame` selects the frame of a LAMMPS dump (0-based; −1 = last).
/// A 2D read of a 3D file takes x and y.
template <int N>
std::vector<std::array<double, N>> read_points(const std::filesystem::path& file, int frame = 0);

}  // namespace shockfield::geometry
