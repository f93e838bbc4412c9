#pragma once
// Robust geometric predicates in 2D and 3D (the "kernel" the Delaunay division is built on; every
// algorithm on top is combinatorics). Each predicate returns the exact sign of a determinant of
// double coordinates: first a floating-point evaluation with a forward error bound (Shewchuk 1997,
// §4: |error| <= c·ε·permanent); when the bound does not separate the value from zero, the same
// determinant in exact expansion arithmetic (geometry/expansion.hpp).
//
//   orient<N>(p0..pN)        = det[ p_i − p_N ]_{i<N}  = det[ (p_i, 1) ]             (N+1 points)
//   in_sphere<N>(p0..pN+1)   = det[ p_i − q, |p_i − q|² ]_{i<=N}, q = p_{N+1}
//                            = det[ (p_i, |p_i|², 1) ]                                (N+2 points)
//
// orient > 0: the simplex p0..pN is positively oriented (2D: counter-clockwise). For a positively
// oriented simplex, in_sphere > 0 when q is strictly inside its circumsphere (circumcircle in 2D).
//
// Exact degeneracies (q on the sphere) are resolved by symbolic perturbation of the lift
// (Edelsbrunner & Mücke 1990; the form used by Devillers & Teillaud 2011 for Delaunay): point i is
// lifted to |p_i|² + ε^{rank_i}, ε infinitesimal, the smallest rank perturbed most. The perturbed
// determinant is D + Σ_i ε^{rank_i} (−1)^{i+N} orient(the points without i), so its sign is that of
// D, else of the first non-zero term in increasing rank. It is never zero when p0..pN span a
// simplex, and it is a consistent rule (one global rank per point), so the Delaunay division of
// cospherical points is one valid triangulation of them.
#include <array>
#include <cstdint>

namespace shockfield::geometry {

template <int N>
using PointRefs = std::array<const double*, N>;

/// Sign (−1, 0, 1) of orient<N>; p[i] points at N coordinates.
template <int N>
int orient(const PointRefs<N + 1>& p);

/// Sign of in_sphere<N> (q = p[N+1]).
template <int N>
int in_sphere(const PointRefs<N + 2>& p);

/// in_sphere<N> with the symbolic perturbation above; rank[i] is a global, distinct rank of point i
/// (its index in the point set). Zero only when all N+2 points lie in one hyperplane.
template <int N>
int in_sphere_perturbed(const PointRefs<N + 2>& p, const std::array<std::int64_t, N + 2>& rank);

/// The exact signs without the floating-point filter (tests compare the filtered ones with these).
template <int N>
int orient_exact(const PointRefs<N + 1>& p);
template <int N>
int in_sphere_exact(const PointRefs<N + 2>& p);

}  // namespace shockfield::geometry
