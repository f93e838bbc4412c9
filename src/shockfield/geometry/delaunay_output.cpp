// Delaunay mesh and cluster files (delaunay_output.hpp).
#include "shockfield/geometry/delaunay_output.hpp"

#include <fmt/format.h>

#include "shockfield/core/unit_names.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::geometry {

namespace {

// Analysis meshes are written as the runs' fields are: zlib-compressed binary, Float64 positions.
const io::VtkFormat kMeshFormat(io::VtkEncoding::Zlib, io::VtkPrecision::Float64);

// The unit of a measure of `dimension` lengths of `length_unit` ("A" -> "A3"; "1" and "unknown" stay).
std::string power_unit(const std::string& length_unit, int dimension) {
  return length_unit == "1" || length_unit == "unknown" ? length_unit : length_unit + std::to_string(dimension);
}

}  // namespace

template <int N>
void write_delaunay_vtu(const std::filesystem::path& file, const DelaunayDivision<N>& d, const PointArrays& point_data,
                        const std::string& length_unit) {
  io::VtkCells mesh;
  mesh.position_units = length_unit;
  mesh.vertices_per_cell = N + 1;
  mesh.xyz.reserve(3 * d.points.size());
  for (const auto& p : d.points) mesh.xyz.insert(mesh.xyz.end(), {p[0], p[1], N == 3 ? p[N - 1] : 0.0});
  mesh.connectivity.reserve(d.simplices.size() * (N + 1));
  for (const auto& s : d.simplices)
    for (int i = 0; i <= N; ++i) mesh.connectivity.push_back(s[i]);
  io::VtkArray volume{"volume", 1, {}, power_unit(length_unit, N)};
  for (std::size_t c = 0; c < d.simplices.size(); ++c) volume.values.push_back(simplex_volume<N>(d, c));
  mesh.cell_data.push_back(std::move(volume));
  for (const auto& [name, values] : point_data) mesh.point_data.push_back({name, 1, values, "1", true});
  io::write_vtu(file, mesh, kMeshFormat);
}

SurfaceMesh surface_mesh(std::size_t point_count, const std::vector<std::array<std::int32_t, 3>>& triangles) {
  SurfaceMesh mesh;
  std::vector<std::int32_t> index(point_count, -1);
  mesh.triangles.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::array<std::int32_t, 3> renumbered{};
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = t[static_cast<std::size_t>(k)];
      if (index[static_cast<std::size_t>(v)] < 0) {
        index[static_cast<std::size_t>(v)] = static_cast<std::int32_t>(mesh.used.size());
        mesh.used.push_back(v);
      }
      renumbered[static_cast<std::size_t>(k)] = index[static_cast<std::size_t>(v)];
    }
    mesh.triangles.push_back(renumbered);
  }
  return mesh;
}

void write_surface_vtp(const std::filesystem::path& file,
                       const std::vector<std::array<double, 3>>& points,
                       const std::vector<std::array<std::int32_t, 3>>& triangles, const std::string& length_unit) {
  const SurfaceMesh surface = surface_mesh(points.size(), triangles);
  io::VtkCells mesh;
  mesh.position_units = length_unit;
  for (std::int32_t v : surface.used) mesh.xyz.insert(mesh.xyz.end(), points[v].begin(), points[v].end());
  for (const auto& t : surface.triangles) mesh.connectivity.insert(mesh.connectivity.end(), t.begin(), t.end());
  io::write_vtp_polygons(file, mesh, kMeshFormat);
}

template <int N>
void write_clusters_csv(const std::filesystem::path& file, const DelaunayDivision<N>& d,
                        const std::vector<std::pair<std::string, const PointClusters*>>& clusterings,
                        const std::string& length_unit) {
  io::CheckedOutput out(file);  // a failed write stops with RunError naming the file
  out << "index";
  for (int k = 0; k < N; ++k) out << ',' << units::column_name(std::string(1, "xyz"[k]), length_unit);
  for (const auto& [name, c] : clusterings) out << ',' << name;
  out << '\n';
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    out << i;
    for (double x : d.points[i]) out << fmt::format(",{}", x);
    for (const auto& [name, c] : clusterings) out << ',' << c->label[i];
    out << '\n';
  }
  out.close();
}

template void write_delaunay_vtu<2>(const std::filesystem::path&, const DelaunayDivision<2>&, const PointArrays&,
                                    const std::string&);
template void write_delaunay_vtu<3>(const std::filesystem::path&, const DelaunayDivision<3>&, const PointArrays&,
                                    const std::string&);
template void write_clusters_csv<2>(const std::filesystem::path&, const DelaunayDivision<2>&,
                                    const std::vector<std::pair<std::string, const PointClusters*>>&, const std::string&);
template void write_clusters_csv<3>(const std::filesystem::path&, const DelaunayDivision<3>&,
                                    const std::vector<std::pair<std::string, const PointClusters*>>&, const std::string&);

}  // namespace shockfield::geometry
