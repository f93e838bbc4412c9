#pragma once
// Reading grid fields for `shockfield analyze` (formats in docs/analysis-minkowski.md):
//  - .csv / .txt: CSV grid. One line per row of cells (y = 0 first), values separated by commas;
//    in 3D, slices (z = 0 first) separated by a blank line. `void` or an empty entry marks a void
//    cell. Lines starting with `#` are comments, except `# spacing = h`, `# origin = x y z`,
//    `# units = U` (the values' unit) and `# length_units = U` (the spacing's).
//  - .vtk: legacy VTK, ASCII, DATASET STRUCTURED_POINTS with POINT_DATA or CELL_DATA SCALARS.
//  - .vti: VTK XML ImageData (PointData or CellData), a DataArray in format="ascii", "binary" or
//    "appended" (raw or base64; uncompressed: analysis/vti_binary.hpp).
//  - .pvti: VTK XML PImageData over .vti pieces (analysis/pvti_reader.hpp), the grid they tile.
// For VTK files, `array` picks the data array by name (default: the first scalar array); NaN
// entries mark void cells (ParaView's convention for blanked points). The array's `units`
// attribute and the (P)ImageData's `length_units` (our writers': io/vtk_xml.hpp) give the field's
// units; a .pvd's <Collection time_units> its times' (docs/conventions.md).
//
// A time series is a .pvd collection (what a run writes to its output folder) or a run folder
// holding one .pvd of image data.
#include <string>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// Reads the field in `path` by its extension. Throws InputError naming the file (and line) on
/// anything it cannot read.
GridField read_grid_field(const std::string& path, const std::string& array = "");

struct SeriesEntry {
  double time = 0.0;
  std::string file;  ///< path of the data set (the .pvd's folder joined with its `file`)
  std::string time_units{};  ///< the <Collection>'s time_units ("s", "ps", "1"); empty: not named
};

/// The data sets of a .pvd file, or of the one .pvd in folder `path` whose data sets are .vti or
/// .pvti files, in time order. Throws InputError when there is none, or several in a folder.
std::vector<SeriesEntry> read_series(const std::string& path);

}  // namespace shockfield::analysis
