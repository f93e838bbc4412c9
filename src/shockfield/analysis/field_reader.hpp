#pragma once
// Reading grid fields for `shockfield analyze` (formats in docs/analysis-minkowski.md):
//  - .csv / .txt: CSV grid. One line per row of cells (y = 0 first), values separated by commas;
//    in 3D, slices (z = 0 first) separated by a blank line. `void` or an empty entry marks a void
//    cell. Lines starting with `#` are comments, except `# spacing = h` and `# origin = x y z`.
//  - .vtk: legacy VTK, ASCII, DATASET STRUCTURED_POINTS with POINT_DATA or CELL_DATA SCALARS.
//  - .vti: VTK XML ImageData with a DataArray in format="ascii" (PointData or CellData).
// For VTK files, `array` picks the data array by name (default: the first scalar array); NaN
// entries mark void cells (ParaView's convention for blanked points).
#include <string>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// Reads the field in `path` by its extension. Throws InputError naming the file (and line) on
/// anything it cannot read.
GridField read_grid_field(const std::string& path, const std::string& array = "");

}  // namespace shockfield::analysis
