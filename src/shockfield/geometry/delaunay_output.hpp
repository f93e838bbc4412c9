#pragma once
// Files of a Delaunay division for ParaView and scripts: the mesh as VTK XML UnstructuredGrid
// (.vtu; triangles or tetrahedra, cell data "volume", optional point data arrays) and per-point
// cluster labels as CSV; triangle surfaces as .vtp. The VTK files go through the output layer
// (io/vtk_xml: zlib-compressed binary, Float64, units on every array; docs/conventions.md).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/delaunay_clusters.hpp"

namespace shockfield::geometry {

/// Point data arrays: name and one label per point (cluster numbers: written as Int32).
using PointArrays = std::vector<std::pair<std::string, std::vector<double>>>;

/// The division's points (in `length_unit`, "1" when unknown), its simplices with their volume
/// (area in 2D) in that unit's square or cube, and the labels of `point_data`.
template <int N>
void write_delaunay_vtu(const std::filesystem::path& file, const DelaunayDivision<N>& d, const PointArrays& point_data,
                        const std::string& length_unit);

/// A triangle surface on its own points: `used` lists the indices (into the full point list) of
/// the points the triangles use, in order of first use; `triangles` index into `used`.
struct SurfaceMesh {
  std::vector<std::int32_t> used;
  std::vector<std::array<std::int32_t, 3>> triangles;
};
SurfaceMesh surface_mesh(std::size_t point_count, const std::vector<std::array<std::int32_t, 3>>& triangles);

/// A triangle surface as VTK XML PolyData (.vtp, polygons) for ParaView: the surface_mesh
/// of the triangles (only the points they use), the points named "points" with the unit of their
/// coordinates (`length_unit`: "A" for atoms, "1" for points of no known unit; docs/conventions.md).
void write_surface_vtp(const std::filesystem::path& file,
                       const std::vector<std::array<double, 3>>& points,
                       const std::vector<std::array<std::int32_t, 3>>& triangles, const std::string& length_unit);

/// CSV: index,x_<unit>,y_<unit>[,z_<unit>],<one column per named clustering>; the coordinates
/// named with `length_unit` as core/unit_names spells it (x_A, x_m; x_unknown for "").
template <int N>
void write_clusters_csv(const std::filesystem::path& file, const DelaunayDivision<N>& d,
                        const std::vector<std::pair<std::string, const PointClusters*>>& clusterings,
                        const std::string& length_unit);

}  // namespace shockfield::geometry
