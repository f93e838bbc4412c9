// shockfield._core's Delaunay division, point clusters and surfaces on numpy arrays
// (python/shockfield/analysis.py's `delaunay` and `surface` wrap them): the functions `shockfield
// analyze geometry` calls (geometry/delaunay.hpp, delaunay_clusters.hpp, point_set_surface.hpp;
// Xu et al. (2015) §3.2.3). Points are a C-contiguous (n, 2) or (n, 3) float64 array, copied once
// into the library's point list; the work runs with the GIL released (it is serial: `threads`
// does not apply).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/delaunay_clusters.hpp"
#include "shockfield/geometry/delaunay_output.hpp"
#include "shockfield/geometry/point_set_surface.hpp"

namespace py = pybind11;
namespace sg = shockfield::geometry;

namespace shockfield::python {
namespace {

template <class T, std::size_t K>
py::array_t<T> rows_to_numpy(const std::vector<std::array<T, K>>& rows) {
  py::array_t<T> out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(K)});
  if (!rows.empty()) std::memcpy(out.mutable_data(), rows.data(), rows.size() * sizeof(rows[0]));
  return out;
}

py::dict clusters_dict(const sg::PointClusters& c) {
  py::dict d;
  d["label"] = to_numpy(c.label);
  d["count"] = c.count;
  std::vector<std::int64_t> size(c.size.begin(), c.size.end());
  d["size"] = to_numpy(size);
  if (!c.simplex_set.empty()) {
    d["simplex_set"] = to_numpy(c.simplex_set);
    d["shared_points"] = c.shared_points;
  }
  return d;
}

template <int N>
py::dict divide(const py::array& points, double cluster_distance, const std::string& rule) {
  std::vector<std::array<double, N>> list(static_cast<std::size_t>(points.shape(0)));
  py::dict out;
  sg::DelaunayDivision<N> d;
  std::vector<std::pair<std::string, sg::PointClusters>> clusterings;
  {
    py::gil_scoped_release release;
    if (!list.empty()) std::memcpy(list.data(), points.data(), list.size() * sizeof(list[0]));
    d = sg::delaunay_division<N>(std::move(list), "points");
    if (cluster_distance > 0.0) {
      if (rule == "xu2015" || rule == "both")
        clusterings.emplace_back("seed_rule", sg::seed_rule_clusters<N>(d, cluster_distance));
      if (rule == "single-linkage" || rule == "both")
        clusterings.emplace_back("single_linkage", sg::single_linkage_clusters<N>(d, cluster_distance));
    }
  }
  out["simplices"] = rows_to_numpy(d.simplices);
  out["neighbours"] = rows_to_numpy(d.neighbours);
  out["representative"] = to_numpy(d.representative);
  out["duplicates"] = d.duplicates;
  out[N == 2 ? "total_area" : "total_volume"] = sg::total_volume<N>(d);
  for (const auto& [name, c] : clusterings) out[py::str(name)] = clusters_dict(c);
  return out;
}

// TypeError / ValueError unless `points` is a C-contiguous float64 array of `columns` columns
// (0: 2 or 3).
void check_points(const py::array& points, int columns) {
  if (points.dtype().num() != py::dtype::of<double>().num())
    throw py::type_error("points: expected dtype float64, got " + std::string(py::str(points.dtype())));
  const std::string expected = columns == 3 ? "an (n, 3) array" : "an (n, 2) or (n, 3) array";
  if (points.ndim() != 2 || (columns == 3 && points.shape(1) != 3) || (points.shape(1) != 2 && points.shape(1) != 3))
    throw py::value_error("points: expected " + expected + ", got " + std::to_string(points.ndim()) +
                          " dimension(s)" + (points.ndim() == 2 ? " of " + std::to_string(points.shape(1)) + " columns" : ""));
  if (!(points.flags() & py::array::c_style))
    throw py::value_error("points: the array is not C-contiguous; pass numpy.ascontiguousarray(points)");
}

py::dict delaunay(const py::array& points, double cluster_distance, const std::string& rule) {
  check_points(points, 0);
  if (rule != "xu2015" && rule != "single-linkage" && rule != "both")
    throw py::value_error("rule: expected 'xu2015', 'single-linkage' or 'both', got '" + rule + "'");
  if (cluster_distance < 0.0) throw py::value_error("cluster_distance: expected a distance > 0 (or 0: no clusters)");
  return points.shape(1) == 2 ? divide<2>(points, cluster_distance, rule) : divide<3>(points, cluster_distance, rule);
}

// The surface of `analyze geometry --surface-method method` with the ball's radius or the
// sculpting depth `length`: the points the triangles use (as surface.vtp lists them) with their
// indices in `points`, the triangles on them, and the summary.txt numbers.
py::dict surface(const py::array& points, const std::string& method, double length) {
  check_points(points, 3);
  if (method != "delaunay" && method != "pivot" && method != "packing")
    throw py::value_error("method: expected 'delaunay', 'pivot' or 'packing', got '" + method + "'");
  std::vector<std::array<double, 3>> list(static_cast<std::size_t>(points.shape(0)));
  sg::TriangleSurface s;
  sg::SurfaceMesh mesh;
  {
    py::gil_scoped_release release;
    if (!list.empty()) std::memcpy(list.data(), points.data(), list.size() * sizeof(list[0]));
    s = sg::point_set_surface(sg::delaunay_division<3>(std::move(list), "points"), method, length);
    mesh = sg::surface_mesh(s.points.size(), s.triangles);
  }
  std::vector<std::array<double, 3>> used(mesh.used.size());
  for (std::size_t k = 0; k < used.size(); ++k) used[k] = s.points[static_cast<std::size_t>(mesh.used[k])];
  py::dict out;
  out["points"] = rows_to_numpy(used);
  out["point_index"] = to_numpy(mesh.used);
  out["triangles"] = rows_to_numpy(mesh.triangles);
  out["area"] = s.area;
  out["volume"] = s.volume;
  out["euler_characteristic"] = s.euler_characteristic;
  out["manifold"] = s.manifold;
  return out;
}

}  // namespace

void bind_geometry(py::module_& m) {
  m.def("delaunay", &delaunay, py::arg("points"), py::arg("cluster_distance"), py::arg("rule"));
  m.def("surface", &surface, py::arg("points"), py::arg("method"), py::arg("length"));
}

}  // namespace shockfield::python
