#pragma once
// Delaunay division of points in 2D (triangles) and 3D (tetrahedra), by the incremental
// algorithm of Xu et al. (2015) §3.2.3 "Delaunay division" (Fig. 11) — Bowyer–Watson insertion:
//
//   seed step                                          here
//   point tree tp, points taken off it one by one      the points in BRIO rounds, each along a
//                                                      Hilbert curve (spatial_sort.hpp, as CGAL)
//   containing tetrahedron T of size ~20a               the containing simplex in the limit of
//                                                      infinite size: its vertices merged into one
//                                                      vertex at infinity (as in CGAL), see below
//   search the simplices whose circumsphere holds P    locate P by a walk from the last simplex
//   (the set Q)                                        made (orientation tests), then grow Q over
//                                                      neighbours by in-sphere tests
//   remove Q, link each boundary face of Q to P        Triangulation::insert's cavity step; the
//                                                      new cells' faces paired in a hash table
//   remove the simplices sharing a face with T          drop the simplices on the vertex at infinity
//
// Why the infinite simplex: with a finite containing simplex, a hull simplex whose circumsphere
// reaches one of its vertices is never created, so the division misses part of the convex hull
// (points on a sphere lose many). In the limit the test "P inside the circumsphere of a simplex
// through the vertex at infinity" becomes "P strictly beyond the hull face", and for P on the
// face's plane, the answer of the finite simplex across that face (the limit of the same
// determinant, derived in docs/geometry-giso.md).
//
// Robustness: all decisions are exact signs from geometry/predicates (filtered, exact when
// unsure). Degeneracy: points on a common sphere (lattices) are resolved by the symbolic
// perturbation of predicates.hpp with rank = point index, so the result is one valid Delaunay
// triangulation, the same for any insertion order; duplicate points are merged (the first index
// is kept and the others point to it). Fewer than N+1 distinct points, all points on a line (2D)
// or a plane (3D), and non-finite coordinates are InputErrors.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace shockfield::geometry {

template <int N>
struct DelaunayDivision {
  using Point = std::array<double, N>;
  using Simplex = std::array<std::int32_t, N + 1>;
  std::vector<Point> points;
  /// For each point, the index of the first point equal to it (its own index if unique).
  std::vector<std::int32_t> representative;
  /// Positively oriented simplices (orient<N> > 0) of point indices (representatives only).
  std::vector<Simplex> simplices;
  /// neighbours[s][i]: the simplex across the face opposite vertex i, −1 on the convex hull.
  std::vector<Simplex> neighbours;
  std::size_t duplicates = 0;  ///< points merged into an earlier equal point
};

/// Builds the division; throws InputError (naming `source` in the message) on bad input.
template <int N>
DelaunayDivision<N> delaunay_division(std::vector<std::array<double, N>> points,
                                      const std::string& source = "points");

/// Exact checks of a division: every simplex positively oriented, neighbour links symmetric and
/// sharing a face, and the empty-circumsphere property tested locally on every interior face
/// (the vertex across a face is not strictly inside the circumsphere; with a valid triangulation
/// this implies it for every point — Delaunay's lemma). Returns "" or the first failure.
template <int N>
std::string check_delaunay(const DelaunayDivision<N>& d);

/// Signed volume (area in 2D) of simplex s, and the total.
template <int N>
double simplex_volume(const DelaunayDivision<N>& d, std::size_t s);
template <int N>
double total_volume(const DelaunayDivision<N>& d);

}  // namespace shockfield::geometry
