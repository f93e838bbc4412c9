// Peer program (benchmarks and fixtures only, never linked into the library): CGAL's
// Delaunay_triangulation_2/3 (Epick kernel: filtered exact predicates) of a point file
// "x,y[,z]" per line (a header line is skipped). Prints the build time; with an output file,
// writes one simplex per line as sorted 0-based point indices, lines sorted — the format of
// tests/fixtures/giso/*_scipy.txt, so the Delaunay test compares against both peers.
//   cgal_delaunay_peer DIM POINTS.csv [SIMPLICES.txt]
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Dt3 = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb3>>;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Dt2 = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb2>>;

std::vector<std::array<double, 3>> read(const char* file) {
  std::ifstream in(file);
  std::vector<std::array<double, 3>> pts;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || !(std::isdigit(line[0]) || line[0] == '-' || line[0] == '.')) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream w(line);
    std::array<double, 3> p{0, 0, 0};
    w >> p[0] >> p[1] >> p[2];
    pts.push_back(p);
  }
  return pts;
}

template <class Simplices>
void write(const char* file, Simplices s) {
  for (auto& x : s) std::sort(x.begin(), x.end());
  std::sort(s.begin(), s.end());
  std::ofstream out(file);
  out << "# CGAL " << CGAL_VERSION_STR << " Delaunay_triangulation (Epick)\n";
  for (const auto& x : s) {
    for (std::size_t i = 0; i < x.size(); ++i) out << x[i] << (i + 1 < x.size() ? ' ' : '\n');
  }
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s DIM POINTS.csv [SIMPLICES.txt]\n", argv[0]);
    return 2;
  }
  const int dim = std::atoi(argv[1]);
  const auto pts = read(argv[2]);
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  auto cpu_seconds = [&] { return double(std::clock() - c0) / CLOCKS_PER_SEC; };
  if (dim == 3) {
    std::vector<std::pair<K::Point_3, int>> in;
    for (std::size_t i = 0; i < pts.size(); ++i)
      in.emplace_back(K::Point_3(pts[i][0], pts[i][1], pts[i][2]), static_cast<int>(i));
    Dt3 dt(in.begin(), in.end());
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("cgal 3d points %zu tetrahedra %zu seconds %.3f cpu_seconds %.3f\n", pts.size(),
                dt.number_of_finite_cells(), t, cpu_seconds());
    if (argc > 3) {
      std::vector<std::array<int, 4>> s;
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
        s.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                     c->vertex(3)->info()});
      write(argv[3], s);
    }
  } else {
    std::vector<std::pair<K::Point_2, int>> in;
    for (std::size_t i = 0; i < pts.size(); ++i)
      in.emplace_back(K::Point_2(pts[i][0], pts[i][1]), static_cast<int>(i));
    Dt2 dt(in.begin(), in.end());
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("cgal 2d points %zu triangles %zu seconds %.3f cpu_seconds %.3f\n", pts.size(),
                dt.number_of_faces(), t, cpu_seconds());
    if (argc > 3) {
      std::vector<std::array<int, 3>> s;
      for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
        s.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
      write(argv[3], s);
    }
  }
  return 0;
}
