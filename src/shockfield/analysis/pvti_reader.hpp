#pragma once
// Reading a parallel VTK image (.pvti, what a run writes with [output] vtk_pieces > 1; io/vtk_pieces)
// for `shockfield analyze`: the <PImageData> WholeExtent, Origin and Spacing, the array's place
// (PPointData or PCellData), and each <Piece Extent Source> read as a .vti (analysis/field_reader)
// and placed at its extent. The pieces must cover the whole extent (shared boundary points may be
// read twice, they hold the same values); a Source must be a .vti file next to or below the .pvti.
#include <string>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// The field `array` (default: the first scalar array) of the .pvti `path` whose text is `text`.
/// Throws InputError naming the file (and the piece) on anything it cannot read.
GridField read_pvti(const std::string& path, const std::string& text, const std::string& array);

}  // namespace shockfield::analysis
