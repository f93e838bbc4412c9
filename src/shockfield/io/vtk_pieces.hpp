#pragma once
// One VTK frame as one file or as parallel pieces, the way every method writes its grid and
// particle frames ([output] vtk_pieces, docs/conventions.md "VTK files"). With VtkFormat::pieces
// = 1 a frame is the single `<name>.vti` / `<name>.vtp` of io/vtk_xml, byte for byte. With N > 1
// it is VTK's parallel format (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html,
// "Parallel File Formats"): the piece files `<name>/<stem>_<p>.vti|.vtp` written by the same
// writers, and the summary `<name>.pvti` (PImageData: WholeExtent, each piece's Extent and Source,
// PPointData/PCellData declaring the pieces' arrays with their types, components and units) or
// `<name>.pvtp` (PPolyData, PPoints), written last and atomically. A grid is cut into slabs of
// whole cells along its longest axis (the slowest of equal ones); neighbouring pieces share the
// plane of points between them, as VTK's point data needs. Particles are cut into N ranges of
// consecutive particles; a range may be empty (fewer particles than pieces), its piece is a valid
// file of zero points.
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::io {

/// The extents of the pieces of a grid of `points` cut into `pieces` slabs: at most one per cell
/// along the cut axis (a grid of a single point is one piece), together covering every point and
/// every cell once, neighbours sharing their boundary plane of points.
std::vector<VtkExtent> image_piece_extents(const std::array<std::size_t, 3>& points, int pieces);

/// The part of `image` within `extent`: its points' values, its cells' values, its hidden flags.
VtkImage image_piece(const VtkImage& image, const VtkExtent& extent);

/// Writes a grid frame `<folder>/<name>.vti`, or with format.pieces > 1 `<folder>/<name>.pvti` and
/// its pieces; returns the file written relative to `folder`, the entry for the .pvd.
std::string write_image_frame(const std::filesystem::path& folder, const std::string& name, const VtkImage& image,
                              VtkFormat format);

/// Writes a particle frame `<folder>/<name>.vtp` (write_vtp), or with format.pieces > 1
/// `<folder>/<name>.pvtp` and its pieces; returns the file written relative to `folder`.
std::string write_points_frame(const std::filesystem::path& folder, const std::string& name,
                               const std::vector<double>& xyz, const std::vector<VtkArray>& point_data,
                               VtkFormat format, const std::string& position_units = "m");

}  // namespace shockfield::io
