// Delaunay mesh and cluster files (delaunay_output.hpp).
#include "shockfield/geometry/delaunay_output.hpp"

#include <fmt/format.h>

#include "shockfield/io/checked_file.hpp"

namespace shockfield::geometry {

template <int N>
void write_delaunay_vtu(const std::filesystem::path& file, const DelaunayDivision<N>& d,
                        const PointArrays& point_data) {
  io::CheckedOutput out(file);  // a failed write stops with RunError naming the file
  const std::size_t np = d.points.size(), nc = d.simplices.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  out << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", np, nc);
  out << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const auto& p : d.points)
    out << fmt::format("{} {} {}\n", p[0], p[1], N == 3 ? p[N - 1] : 0.0);
  out << "        </DataArray>\n      </Points>\n      <Cells>\n";
  out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& s : d.simplices) {
    for (int i = 0; i <= N; ++i) out << s[i] << (i < N ? ' ' : '\n');
  }
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t c = 0; c < nc; ++c) out << (c + 1) * (N + 1) << '\n';
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" "
         "format=\"ascii\">\n";
  const int vtk_type = N == 2 ? 5 : 10;  // VTK_TRIANGLE, VTK_TETRA
  for (std::size_t c = 0; c < nc; ++c) out << vtk_type << '\n';
  out << "        </DataArray>\n      </Cells>\n      <CellData Scalars=\"volume\">\n";
  out << "        <DataArray type=\"Float64\" Name=\"volume\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < nc; ++c) out << fmt::format("{:.12g}\n", simplex_volume<N>(d, c));
  out << "        </DataArray>\n      </CellData>\n      <PointData>\n";
  for (const auto& [name, values] : point_data) {
    out << fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n", name);
    for (double v : values) out << fmt::format("{:.12g}\n", v);
    out << "        </DataArray>\n";
  }
  out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  out.close();
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
  const SurfaceMesh mesh = surface_mesh(points.size(), triangles);
  io::CheckedOutput out(file);  // a failed write stops with RunError naming the file
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PolyData>\n";
  out << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfPolys=\"{}\">\n", mesh.used.size(),
                     triangles.size());
  out << fmt::format("      <Points>\n        <DataArray type=\"Float64\" Name=\"points\" NumberOfComponents=\"3\" "
                     "format=\"ascii\" units=\"{}\">\n", length_unit);
  for (std::int32_t v : mesh.used)
    out << fmt::format("{} {} {}\n", points[v][0], points[v][1], points[v][2]);
  out << "        </DataArray>\n      </Points>\n      <Polys>\n";
  out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : mesh.triangles) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t c = 0; c < triangles.size(); ++c) out << 3 * (c + 1) << '\n';
  out << "        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  out.close();
}

template <int N>
void write_clusters_csv(const std::filesystem::path& file, const DelaunayDivision<N>& d,
                        const std::vector<std::pair<std::string, const PointClusters*>>& clusterings) {
  io::CheckedOutput out(file);  // a failed write stops with RunError naming the file
  out << "index," << (N == 2 ? "x,y" : "x,y,z");
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

template void write_delaunay_vtu<2>(const std::filesystem::path&, const DelaunayDivision<2>&,
                                    const PointArrays&);
template void write_delaunay_vtu<3>(const std::filesystem::path&, const DelaunayDivision<3>&,
                                    const PointArrays&);
template void write_clusters_csv<2>(const std::filesystem::path&, const DelaunayDivision<2>&,
                                    const std::vector<std::pair<std::string, const PointClusters*>>&);
template void write_clusters_csv<3>(const std::filesystem::path&, const DelaunayDivision<3>&,
                                    const std::vector<std::pair<std::string, const PointClusters*>>&);

}  // namespace shockfield::geometry
