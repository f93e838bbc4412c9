#pragma once
// Proximity queries on the SHT, built on its two generic searches: the paper's minimum searcher
// MS2 (nearest object to a point, Xu et al. 2015 §3.2.3 (II)) and its k-nearest generalisation,
// and a radius query as a conditional search. Distances are to an object's bounding box (0 inside
// it), which for points is the distance to the point. MS2's range functions use the cube's box
// rather than its circumsphere (m(b) = distance to the box <= the paper's |c_b − r_o| − √3 d_b),
// a tighter bound with the same meaning.
#include <cmath>
#include <vector>

#include "shockfield/geometry/space_tree.hpp"

namespace shockfield::geometry {

/// Squared distance from q to the box of object id (as the adaptor gives it now).
template <int N, class Tree>
double box_distance2(const Tree& tree, typename Tree::Id id, const std::array<double, N>& q) {
  std::array<double, N> lo, hi;
  tree.objects().bounds(id, lo, hi);
  return distance2_to_box<N>(q, lo, hi);
}

/// MS2's range of a cube for the squared distance to q: m(b) = distance to its region, and no
/// M(b) (+inf): depth first with the nearest sub-cube first, the first leaf reached already
/// bounds the search, so the distance to a cube's farthest point is not worth computing for
/// every sub-cube ranked. Offers the form over all sub-cubes at once (sub_cube_distances2).
template <int N>
auto distance2_range(const std::array<double, N>& q) {
  return Overloaded{
      [&q](const TreeCube<N>& cube) {
        return std::pair{cube.distance2_to(q), std::numeric_limits<double>::infinity()};
      },
      [&q](const TreeCube<N>& cube, const std::array<double, (1 << N)>& sub_margins,
           std::array<double, (1 << N)>& m) { sub_cube_distances2<N>(cube, sub_margins, q, m); }};
}

struct Neighbour {
  double distance;
  std::uint32_t id;
};

/// Squared distance from q to an object: to its box for a held object, and also in the form
/// over coordinate columns of points (out[i] = |q − p_i|², the same sum in the same order as
/// TreeObject::distance2_to, so bitwise equal).
template <int N, class Tree>
auto distance2_value(const std::array<double, N>& q) {
  return Overloaded{
      [&q](const typename Tree::Object& o) { return o.distance2_to(q); },
      [&q](const std::array<const double*, N>& axes, std::size_t count, double* out) {
        for (std::size_t i = 0; i < count; ++i) {
          double d2 = 0.0;
          for (int k = 0; k < N; ++k) d2 += (axes[k][i] - q[k]) * (axes[k][i] - q[k]);
          out[i] = d2;
        }
      }};
}

/// The k objects nearest to q, nearest first (MS2 for k = 1).
template <int N, class Tree>
std::vector<Neighbour> k_nearest(const Tree& tree, const std::array<double, N>& q, std::size_t k) {
  InlineVector<typename Tree::Found, 16> found;  // no allocation but the answer's for k <= 16
  tree.minimum_search_into(k, distance2_range<N>(q), distance2_value<N, Tree>(q), found);
  std::vector<Neighbour> out;
  out.reserve(found.size());
  for (const auto& f : found) out.push_back({std::sqrt(f.value), f.id});
  return out;
}

/// The nearest object to q (MS2); distance +inf and id 0 for an empty tree. Allocates nothing.
template <int N, class Tree>
Neighbour nearest(const Tree& tree, const std::array<double, N>& q) {
  InlineVector<typename Tree::Found, 1> found;
  tree.minimum_search_into(1, distance2_range<N>(q), distance2_value<N, Tree>(q), found);
  if (found.empty()) return {std::numeric_limits<double>::infinity(), 0};
  return {std::sqrt(found.front().value), found.front().id};
}

/// Every object whose box comes within distance r of q (<= r), in no particular order.
template <int N, class Tree>
std::vector<std::uint32_t> within_radius(const Tree& tree, const std::array<double, N>& q,
                                         double r) {
  std::vector<std::uint32_t> out;
  const double r2 = r * r;
  const auto may_contain = Overloaded{
      [&](const TreeCube<N>& cube) { return cube.distance2_to(q) <= r2; },
      [&](const TreeCube<N>& cube, const std::array<double, (1 << N)>& sub_margins) {
        std::array<double, (1 << N)> d2;
        sub_cube_distances2<N>(cube, sub_margins, q, d2);
        unsigned open = 0;
        for (int b = 0; b < (1 << N); ++b) open |= unsigned(d2[b] <= r2) << b;
        return open;
      }};
  tree.conditional_search(may_contain,
                          [&](const typename Tree::Object& o) { return o.distance2_to(q) <= r2; },
                          [&](typename Tree::Id id) {
                            out.push_back(id);
                            return true;
                          });
  return out;
}

}  // namespace shockfield::geometry
