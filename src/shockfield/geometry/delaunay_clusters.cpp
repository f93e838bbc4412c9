// Clusters from a Delaunay division (delaunay_clusters.hpp).
#include "shockfield/geometry/delaunay_clusters.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "shockfield/core/error.hpp"

namespace shockfield::geometry {
namespace {

struct DisjointSets {
  std::vector<std::int32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

template <int N>
double edge_length(const DelaunayDivision<N>& d, std::int32_t a, std::int32_t b) {
  double s = 0.0;
  for (int k = 0; k < N; ++k) s += (d.points[a][k] - d.points[b][k]) * (d.points[a][k] - d.points[b][k]);
  return std::sqrt(s);
}

void check_distance(double critical_distance) {
  if (!(critical_distance > 0.0) || !std::isfinite(critical_distance))
    throw InputError(fmt::format("cluster critical distance must be a positive finite length, got {}",
                                 critical_distance));
}

/// Labels from a root per point: clusters numbered by their lowest point; duplicates follow their
/// representative.
template <int N>
PointClusters label_points(const DelaunayDivision<N>& d, const std::vector<std::int32_t>& root) {
  PointClusters c;
  const std::size_t n = d.points.size();
  c.label.assign(n, -1);
  std::vector<std::int32_t> number(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t r = root[d.representative[i]];
    if (number[r] < 0) {
      number[r] = static_cast<std::int32_t>(c.count++);
      c.size.push_back(0);
    }
    c.label[i] = number[r];
    ++c.size[number[r]];
  }
  return c;
}

}  // namespace

template <int N>
PointClusters seed_rule_clusters(const DelaunayDivision<N>& d, double critical_distance) {
  check_distance(critical_distance);
  const std::size_t ns = d.simplices.size();
  // Keep a simplex unless its shortest edge is longer than d.
  std::vector<char> kept(ns, 0);
  for (std::size_t s = 0; s < ns; ++s) {
    double shortest = INFINITY;
    for (int i = 0; i <= N; ++i)
      for (int j = i + 1; j <= N; ++j)
        shortest = std::min(shortest, edge_length<N>(d, d.simplices[s][i], d.simplices[s][j]));
    kept[s] = !(shortest > critical_distance);
  }
  // Face-connected sets of kept simplices (flood fill through shared faces).
  std::vector<std::int32_t> set(ns, -1), stack;
  std::int32_t sets = 0;
  for (std::size_t s0 = 0; s0 < ns; ++s0) {
    if (!kept[s0] || set[s0] >= 0) continue;
    set[s0] = sets;
    stack.assign(1, static_cast<std::int32_t>(s0));
    while (!stack.empty()) {
      const std::int32_t s = stack.back();
      stack.pop_back();
      for (std::int32_t n : d.neighbours[s])
        if (n >= 0 && kept[n] && set[n] < 0) {
          set[n] = sets;
          stack.push_back(n);
        }
    }
    ++sets;
  }
  // A point takes the lowest set among its simplices; its root is that set's lowest point.
  const std::size_t np = d.points.size();
  std::vector<std::int32_t> point_set(np, -1), set_root(sets, -1);
  std::vector<char> shared(np, 0);
  for (std::size_t s = 0; s < ns; ++s)
    if (set[s] >= 0)
      for (std::int32_t v : d.simplices[s]) {
        if (point_set[v] >= 0 && point_set[v] != set[s]) shared[v] = 1;
        if (point_set[v] < 0 || set[s] < point_set[v]) point_set[v] = set[s];
      }
  for (std::size_t i = 0; i < np; ++i)
    if (point_set[i] >= 0 && set_root[point_set[i]] < 0)
      set_root[point_set[i]] = static_cast<std::int32_t>(i);
  std::vector<std::int32_t> root(np);
  for (std::size_t i = 0; i < np; ++i)
    root[i] = point_set[i] >= 0 ? set_root[point_set[i]] : static_cast<std::int32_t>(i);
  PointClusters c = label_points<N>(d, root);
  c.simplex_set = std::move(set);
  for (std::size_t i = 0; i < np; ++i) c.shared_points += shared[d.representative[i]];
  return c;
}

template <int N>
PointClusters single_linkage_clusters(const DelaunayDivision<N>& d, double critical_distance) {
  check_distance(critical_distance);
  DisjointSets sets(d.points.size());
  for (const auto& s : d.simplices)
    for (int i = 0; i <= N; ++i)
      for (int j = i + 1; j <= N; ++j)
        if (edge_length<N>(d, s[i], s[j]) < critical_distance) sets.join(s[i], s[j]);
  std::vector<std::int32_t> root(d.points.size());
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = sets.find(static_cast<std::int32_t>(i));
  return label_points<N>(d, root);
}

template PointClusters seed_rule_clusters<2>(const DelaunayDivision<2>&, double);
template PointClusters seed_rule_clusters<3>(const DelaunayDivision<3>&, double);
template PointClusters single_linkage_clusters<2>(const DelaunayDivision<2>&, double);
template PointClusters single_linkage_clusters<3>(const DelaunayDivision<3>&, double);

}  // namespace shockfield::geometry
