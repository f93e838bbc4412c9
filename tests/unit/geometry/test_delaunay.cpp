// Delaunay division against SciPy/Qhull and CGAL (fixtures from tests/fixtures/giso/make_*_fixtures.*),
// the exact empty-circumsphere property (local on every face, and brute force on a small set),
// total volume against the convex hull, and degenerate input: lattices (every quadruple of a
// square cocircular, 10^5-point simple cubic and fcc), lattice points on a sphere, duplicates, and
// rejected input. Volume tolerance 1e-12 relative: a sum of ~10^4 double volumes whose exact sum
// equals the hull's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/point_file.hpp"
#include "shockfield/geometry/predicates.hpp"

namespace shockfield::geometry {
namespace {

template <int N>
std::vector<std::array<std::int32_t, N + 1>> sorted_simplices(const DelaunayDivision<N>& d) {
  auto s = d.simplices;
  for (auto& x : s) std::sort(x.begin(), x.end());
  std::sort(s.begin(), s.end());
  return s;
}

template <int N>
std::vector<std::array<std::int32_t, N + 1>> read_peer(const std::string& file, double& volume) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::string line;
  std::getline(in, line);
  if (const auto at = line.find("hull_volume"); at != std::string::npos)
    volume = std::stod(line.substr(at + 12));
  std::vector<std::array<std::int32_t, N + 1>> out;
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::array<std::int32_t, N + 1> s;
    for (auto& v : s) w >> v;
    out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <int N>
void compare_with_peer(const std::string& name) {
  const auto pts = read_points<N>("fixtures/giso/" + name + "_points.csv").points;
  const auto d = delaunay_division<N>(pts);
  ASSERT_EQ(check_delaunay<N>(d), "");
  double hull = 0;
  const auto scipy = read_peer<N>("fixtures/giso/" + name + "_scipy.txt", hull);
  EXPECT_EQ(sorted_simplices<N>(d), scipy) << name;
  EXPECT_NEAR(total_volume<N>(d), hull, 1e-12 * hull) << name;
  double unused = 0;
  const auto cgal = read_peer<N>("fixtures/giso/" + name + "_cgal.txt", unused);
  EXPECT_EQ(sorted_simplices<N>(d), cgal) << name;
}

TEST(Delaunay, SameSimplicesAsScipyQhullAndCgal) {
  compare_with_peer<2>("uniform2d");
  compare_with_peer<3>("uniform3d");
  compare_with_peer<3>("blobs3d");
}

TEST(Delaunay, EmptyCircumsphereByBruteForce) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::array<double, 3>> pts(300);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  const auto d = delaunay_division<3>(pts);
  ASSERT_EQ(check_delaunay<3>(d), "");
  for (const auto& s : d.simplices)
    for (std::size_t q = 0; q < pts.size(); ++q)
      ASSERT_LE(in_sphere<3>({pts[s[0]].data(), pts[s[1]].data(), pts[s[2]].data(),
                              pts[s[3]].data(), pts[q].data()}),
                0);
}

/// Hull faces (faces with no neighbour), and the volume they enclose by the divergence theorem.
template <int N>
std::size_t hull_faces(const DelaunayDivision<N>& d) {
  std::size_t f = 0;
  for (const auto& nb : d.neighbours) f += std::count(nb.begin(), nb.end(), -1);
  return f;
}

TEST(Delaunay, SquareLatticeEveryQuadrupleCocircular) {
  std::vector<std::array<double, 2>> pts;
  const int m = 300;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) pts.push_back({0.5 * i, 0.5 * j});
  const auto d = delaunay_division<2>(pts);
  ASSERT_EQ(check_delaunay<2>(d), "");
  EXPECT_EQ(d.simplices.size(), 2u * (m - 1) * (m - 1));
  const double side = 0.5 * (m - 1);
  EXPECT_NEAR(total_volume<2>(d), side * side, 1e-12 * side * side);
}

std::vector<std::array<double, 3>> lattice(int cells, bool fcc, double a) {
  std::vector<std::array<double, 3>> pts;
  const std::array<std::array<double, 3>, 4> basis{{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}}};
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (int b = 0; b < (fcc ? 4 : 1); ++b)
          pts.push_back({a * (i + basis[b][0]), a * (j + basis[b][1]), a * (k + basis[b][2])});
  return pts;
}

void check_lattices(int sc_cells, int fcc_cells) {
  for (bool fcc : {false, true}) {
    const int cells = fcc ? fcc_cells : sc_cells;
    const double a = 3.615;
    const auto pts = lattice(cells, fcc, a);
    const auto d = delaunay_division<3>(pts);
    ASSERT_EQ(check_delaunay<3>(d), "") << (fcc ? "fcc" : "sc");
    // sc: the hull is the cube of side (cells−1)a. fcc: it lies between that cube (the corner
    // sites) and the points' bounding box of side (cells−0.5)a.
    const double v = total_volume<3>(d);
    if (!fcc) {
      const double side = (cells - 1) * a;
      EXPECT_NEAR(v, side * side * side, 1e-11 * side * side * side);
    } else {
      const double lo = std::pow((cells - 1) * a, 3), hi = std::pow((cells - 0.5) * a, 3);
      EXPECT_GT(v, lo);
      EXPECT_LT(v, hi);
    }
    std::set<std::int32_t> used;
    for (const auto& s : d.simplices) used.insert(s.begin(), s.end());
    EXPECT_EQ(used.size(), pts.size());  // every lattice point is a vertex
  }
}

// Every in-sphere test on a lattice is degenerate or near it and goes to the exact (integer)
// stage: about 5.5 s of CPU for 10^5 points with the exact checks (was 17 s with expansions only),
// so the suite runs 9 261 and 10 976 points (0.8 s) and the 10^5-point version is kept for a
// manual run (--gtest_also_run_disabled_tests --gtest_filter='*Lattices*').
TEST(Delaunay, SimpleCubicAndFccLattices) { check_lattices(21, 14); }
TEST(Delaunay, DISABLED_SimpleCubicAndFccLatticesOf1e5Points) { check_lattices(46, 29); }

TEST(Delaunay, PointsOnASphereRandomAndExactlyCospherical) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  std::vector<std::array<double, 3>> random_sphere(3000);
  for (auto& p : random_sphere) {
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    p = {x / r, y / r, z / r};
  }
  // Integer points with x² + y² + z² = 101: every one of them on one sphere (exact degeneracy).
  std::vector<std::array<double, 3>> lattice_sphere;
  for (int x = -10; x <= 10; ++x)
    for (int y = -10; y <= 10; ++y)
      for (int z = -10; z <= 10; ++z)
        if (x * x + y * y + z * z == 101) lattice_sphere.push_back({double(x), double(y), double(z)});
  ASSERT_GT(lattice_sphere.size(), 50u);
  for (const auto* pts : {&random_sphere, &lattice_sphere}) {
    const auto d = delaunay_division<3>(*pts);
    ASSERT_EQ(check_delaunay<3>(d), "");
    // All points are hull vertices and the hull is a triangulated sphere: F = 2V − 4.
    EXPECT_EQ(hull_faces<3>(d), 2 * pts->size() - 4);
  }
}

TEST(Delaunay, DuplicatesAreMerged) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 3>> pts(500);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  const auto unique = delaunay_division<3>(pts);
  for (int i = 0; i < 100; ++i) pts.push_back(pts[i * 3]);
  const auto d = delaunay_division<3>(pts);
  ASSERT_EQ(check_delaunay<3>(d), "");
  EXPECT_EQ(d.duplicates, 100u);
  EXPECT_EQ(d.representative[500], 0);
  EXPECT_EQ(d.representative[599], 297);
  EXPECT_EQ(sorted_simplices<3>(d), sorted_simplices<3>(unique));
}

template <int N>
void expect_rejected(std::vector<std::array<double, N>> pts, const std::string& text) {
  try {
    delaunay_division<N>(std::move(pts), "in.csv");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(Delaunay, BadInputIsRejectedWithAMessage) {
  expect_rejected<3>({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}, {0, 0, 1}},
                     "in.csv: point 3 has a non-finite coordinate");
  expect_rejected<3>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                     "3 distinct points; a 3D Delaunay division needs at least 4");
  expect_rejected<3>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 3, 0}},
                     "all 5 distinct points lie on one plane");
  expect_rejected<2>({{0, 0}, {1, 1}, {2, 2}, {-3, -3}}, "all 4 distinct points lie on one line");
}

}  // namespace
}  // namespace shockfield::geometry
