#pragma once
// Reading the points of a particle frame for `shockfield analyze geometry`: a VTK XML PolyData
// file (.vtp: what MPM, PD, granular and macroparticle runs write, io/particle_frame, io/vtk_xml)
// or its parallel summary (.pvtp, [output] vtk_pieces > 1: each <Piece Source> a .vtp next to or
// below it, read in order and joined). The <Points> array of every <Piece> (3 components; ascii,
// inline base64 or appended raw/base64, uncompressed or zlib: analysis/vti_binary) and its `units`
// attribute (io/vtk_xml writes units="m" for the SI methods), and one named scalar point array
// with its units (what `analyze minkowski|stats|similarity --bin-size` bins); and MD's LAMMPS dumps
// for the same binning. Lives beside the .vti readers it shares the binary decoding with.
#include <string>
#include <vector>

namespace shockfield::analysis {

struct PointFrame {
  std::vector<double> xyz;     ///< x, y, z interleaved
  std::string position_units;  ///< the Points array's units attribute; empty: not named
  std::vector<double> values;  ///< the named point array's values, one per point (empty: none named)
  std::string values_units;    ///< its units attribute; empty: not named
};

/// The points of the .vtp or .pvtp file `path` and, when `array` names one, that scalar point
/// array; or of a LAMMPS text dump of one frame (a file whose first line starts with "ITEM:", as
/// MD writes dumps/dump.<step>.lammpstrj): its positions in its ITEM: UNITS style's length unit
/// (Å without one: metal units) and the column `array` (no unit: a dump names none). Throws
/// InputError naming the file (and the piece) on anything it cannot read: no <Points>, no such
/// array or column, a count the file cannot hold, a non-finite number, a dump of several frames.
PointFrame read_point_frame(const std::string& path, const std::string& array = "");

/// Whether `path` is a particle frame read_point_frame reads: a .vtp, a .pvtp or a LAMMPS dump.
bool is_point_frame_file(const std::string& path);

}  // namespace shockfield::analysis
