#pragma once
// Insertion order for incremental Delaunay construction: a biased randomized insertion order
// (BRIO, Amenta, Choi & Rote 2003) whose rounds are each sorted along a Hilbert curve, the order
// CGAL's spatial_sort gives its Delaunay_triangulation_3. Consecutive points are close (the
// walk from the last simplex made is short), and the random rounds keep the expected cost of
// randomized insertion on any input.
#include <array>
#include <cstdint>
#include <vector>

namespace shockfield::geometry {

/// Hilbert index of a cell of a 2^bits grid in N dimensions (N * bits <= 64): Skilling (2004)'s
/// "axes to transpose" followed by the interleaving of the transposed bits, most significant first.
template <int N>
std::uint64_t hilbert_index(std::array<std::uint32_t, N> cell, int bits);

/// The points `ids` of `points` in BRIO order: a random permutation (fixed seed) cut into rounds
/// of sizes ..., n/8, n/4, n/2 (the first round at most 64 points), each round sorted by the
/// Hilbert index of its points on a 2^(64/N)-cell grid over the points' bounding box.
template <int N>
std::vector<std::int32_t> brio_hilbert_order(const std::vector<std::array<double, N>>& points,
                                             std::vector<std::int32_t> ids);

}  // namespace shockfield::geometry
