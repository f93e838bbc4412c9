// GISO benchmark (bench/RESULTS.md "## GISO"): Delaunay division and SHT queries.
//   delaunay_bench generate DIM N FILE   uniform random points in the unit cube, CSV (seeded)
//   delaunay_bench generate-fcc N FILE   an fcc crystal of about N atoms (lattice constant 1, a
//                                        cube of unit cells) with Gaussian thermal displacements
//                                        of 0.03 per coordinate (seeded), CSV
//   delaunay_bench generate-lattice sc|fcc N FILE [A]   the exact lattice (no displacements) of
//                                        lattice constant A (default 1), CSV
//   delaunay_bench delaunay DIM FILE     time of our Delaunay division of the points of FILE
//   delaunay_bench queries N Q [fcc]     nearest, 8-nearest and radius query rates (per second
//                                        of the thread's CPU time) of the SHT beside nanoflann's
//                                        kd-tree on the same N points (uniform, or the
//                                        perturbed fcc crystal of generate-fcc), Q uniform
//                                        queries in the points' box; the answers are compared
//                                        (must be equal)
// bench/delaunay_compare.sh runs these beside CGAL (cgal_delaunay_peer) and SciPy/Qhull.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <time.h>
#include <cstdio>
#include <fstream>
#include <nanoflann.hpp>
#include <random>
#include <stdexcept>
#include <string>

#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/point_file.hpp"
#include "shockfield/geometry/space_tree.hpp"
#include "shockfield/geometry/space_tree_queries.hpp"

namespace sg = shockfield::geometry;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// CPU time of the calling thread, s (the machine is shared: wall time measures the load).
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::vector<std::array<double, 3>> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 3>> p(n);
  for (auto& x : p) x = {u(rng), u(rng), u(rng)};
  return p;
}

void write_csv(const std::string& file, const std::vector<std::array<double, 3>>& points, int dim) {
  std::ofstream out(file);
  out << (dim == 2 ? "x,y\n" : "x,y,z\n");
  for (const auto& p : points)
    out << (dim == 2 ? fmt::format("{:.17g},{:.17g}\n", p[0], p[1])
                     : fmt::format("{:.17g},{:.17g},{:.17g}\n", p[0], p[1], p[2]));
}

/// A cube of unit cells (lattice constant a) of about `atoms` atoms: simple cubic, or fcc with 4
/// atoms per cell at (0,0,0), (½,½,0), (½,0,½), (0,½,½); each coordinate displaced by a Gaussian of
/// standard deviation sigma (σ = 0.03 is about copper's room-temperature vibration, √⟨u²⟩ ≈
/// 0.08–0.1 Å of a = 3.6 Å; σ = 0 leaves the exact lattice, every in-sphere test degenerate).
std::vector<std::array<double, 3>> crystal(const std::string& kind, std::size_t atoms, double sigma,
                                           std::uint64_t seed, double a = 1.0) {
  const std::vector<std::array<double, 3>> fcc{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  const std::vector<std::array<double, 3>> sc{{0, 0, 0}};
  if (kind != "sc" && kind != "fcc") throw std::invalid_argument("lattice kind: sc or fcc");
  const auto& basis = kind == "sc" ? sc : fcc;
  const auto cells = static_cast<int>(std::lround(std::cbrt(double(atoms) / basis.size())));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> thermal(0.0, sigma);
  auto displaced = [&](double x) { return sigma > 0 ? x + thermal(rng) : x; };
  std::vector<std::array<double, 3>> p;
  p.reserve(basis.size() * cells * cells * cells);
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (const auto& b : basis)
          p.push_back(
              {displaced(a * (i + b[0])), displaced(a * (j + b[1])), displaced(a * (k + b[2]))});
  return p;
}

template <int N>
int delaunay(const std::string& file) {
  const auto pts = sg::read_points<N>(file).points;
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  const auto d = sg::delaunay_division<N>(pts, file);
  std::printf("shockfield %dd points %zu simplices %zu seconds %.3f cpu_seconds %.3f\n", N,
              pts.size(), d.simplices.size(), seconds_since(t0),
              double(std::clock() - c0) / CLOCKS_PER_SEC);
  return 0;
}

struct Cloud {  // nanoflann's dataset adaptor
  const std::vector<std::array<double, 3>>& p;
  std::size_t kdtree_get_point_count() const { return p.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t k) const { return p[i][k]; }
  template <class B>
  bool kdtree_get_bbox(B&) const { return false; }
};

int queries(std::size_t n, std::size_t q, bool fcc) {
  const auto pts = fcc ? crystal("fcc", n, 0.03, 11) : uniform(n, 1);
  // Queries uniform in the points' box (the unit cube, or the crystal's cube of cells).
  const double side = fcc ? std::cbrt(pts.size() / 4.0) : 1.0;
  auto qs = uniform(q, 2);
  for (auto& x : qs)
    for (double& c : x) c *= side;
  n = pts.size();
  const double r = side * std::cbrt(30.0 / (4.18879 * n));  // about 30 points per ball
  auto t0 = Clock::now();
  auto adaptor = sg::points_adaptor<3>(n, [&](std::size_t i, int k) { return pts[i][k]; });
  const auto tree = sg::SpaceTree<3, decltype(adaptor)>::with_all(adaptor);
  const double sht_build = seconds_since(t0);
  t0 = Clock::now();
  const Cloud cloud{pts};
  using Kd = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                  3, std::uint32_t>;
  Kd kd(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  const double kd_build = seconds_since(t0);
  // The four query loops run on 20 slices of the queries in turn (SHT, nanoflann, SHT, ...),
  // so that a change of the machine's load mid-run hits both alike.
  std::vector<double> sht_nn(q), kd_nn(q), sht_knn(q), kd_knn(q);
  std::size_t sht_found = 0, kd_found = 0;
  double sht_nearest = 0, kd_nearest = 0, sht_radius = 0, kd_radius = 0, sht_k = 0, kd_k = 0;
  constexpr std::size_t kNeighbours = 8;  // k-nearest: the 8th neighbour's distance compared
  std::vector<std::pair<std::uint32_t, double>> found;  // nanoflann 1.4 (Debian 12)
  constexpr std::size_t kSlices = 20;
  for (std::size_t slice = 0; slice < kSlices; ++slice) {
    const std::size_t from = q * slice / kSlices, to = q * (slice + 1) / kSlices;
    double c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i) sht_nn[i] = sg::nearest<3>(tree, qs[i]).distance;
    sht_nearest += thread_cpu_seconds() - c0;
    c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i) {
      std::uint32_t idx;
      double d2;
      kd.knnSearch(qs[i].data(), 1, &idx, &d2);
      kd_nn[i] = std::sqrt(d2);
    }
    kd_nearest += thread_cpu_seconds() - c0;
    c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i)
      sht_knn[i] = sg::k_nearest<3>(tree, qs[i], kNeighbours).back().distance;
    sht_k += thread_cpu_seconds() - c0;
    c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i) {
      std::array<std::uint32_t, kNeighbours> idx;
      std::array<double, kNeighbours> d2;
      kd.knnSearch(qs[i].data(), kNeighbours, idx.data(), d2.data());
      kd_knn[i] = std::sqrt(d2.back());
    }
    kd_k += thread_cpu_seconds() - c0;
    c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i) sht_found += sg::within_radius<3>(tree, qs[i], r).size();
    sht_radius += thread_cpu_seconds() - c0;
    c0 = thread_cpu_seconds();
    for (std::size_t i = from; i < to; ++i)
      kd_found +=
          kd.radiusSearch(qs[i].data(), r * r, found, nanoflann::SearchParams(32, 0.0f, false));
    kd_radius += thread_cpu_seconds() - c0;
  }
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < q; ++i) mismatches += sht_nn[i] != kd_nn[i] || sht_knn[i] != kd_knn[i];
  std::printf("points %zu (%s) queries %zu radius %.5g\n", n, fcc ? "fcc" : "uniform", q, r);
  std::printf("build: sht %.3f s, nanoflann %.3f s\n", sht_build, kd_build);
  std::printf("nearest: sht %.3g /s, nanoflann %.3g /s, ratio %.2f, mismatches %zu\n",
              q / sht_nearest, q / kd_nearest, kd_nearest / sht_nearest, mismatches);
  std::printf("%zu-nearest: sht %.3g /s, nanoflann %.3g /s, ratio %.2f\n", kNeighbours, q / sht_k,
              q / kd_k, kd_k / sht_k);
  std::printf("radius: sht %.3g /s, nanoflann %.3g /s, ratio %.2f, found %zu vs %zu\n",
              q / sht_radius, q / kd_radius, kd_radius / sht_radius, sht_found, kd_found);
  return mismatches == 0 && sht_found == kd_found ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "generate" && argc == 5) {
      write_csv(argv[4], uniform(std::stoull(argv[3]), 7), std::stoi(argv[2]));
      return 0;
    }
    if (mode == "generate-fcc" && argc == 4) {
      write_csv(argv[3], crystal("fcc", std::stoull(argv[2]), 0.03, 11), 3);
      return 0;
    }
    if (mode == "generate-lattice" && (argc == 5 || argc == 6)) {
      const double a = argc == 6 ? std::stod(argv[5]) : 1.0;
      write_csv(argv[4], crystal(argv[2], std::stoull(argv[3]), 0.0, 0, a), 3);
      return 0;
    }
    if (mode == "delaunay" && argc == 4) return argv[2][0] == '2' ? delaunay<2>(argv[3]) : delaunay<3>(argv[3]);
    if (mode == "queries" && (argc == 4 || (argc == 5 && std::string(argv[4]) == "fcc")))
      return queries(std::stoull(argv[2]), std::stoull(argv[3]), argc == 5);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr,
               "usage: delaunay_bench generate DIM N FILE | generate-fcc N FILE | generate-lattice "
               "sc|fcc N FILE [A] | delaunay DIM FILE "
               "| queries N Q [fcc]\n");
  return 2;
}
