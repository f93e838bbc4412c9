#pragma once
// Clusters of points from their Delaunay division, with a critical distance d (Xu et al. 2015
// §3.2.3, "Cluster construction and analysis method", Fig. 13). Two rules:
//
//  - the paper's rule as written (seed_rule_clusters): remove the simplices whose shortest edge is
//    longer than d; the remaining simplices fall into sets connected through shared faces (the
//    seed grows each set from one simplex through a tree of its open faces, ttr; here a flood fill
//    over the neighbour links does the same). A simplex with one short edge is kept even when its
//    other edges are long, so two groups of points far apart can fall into one cluster.
//  - single linkage (single_linkage_clusters): points joined by Delaunay edges shorter than d. The
//    Euclidean minimum spanning tree is a subgraph of the Delaunay division, so this equals the
//    single-linkage clustering over all pairs of points at threshold d.
#include <cstdint>
#include <vector>

#include "shockfield/geometry/delaunay.hpp"

namespace shockfield::geometry {

struct PointClusters {
  /// Cluster of each point, numbered 0.. in order of each cluster's lowest point index; a
  /// duplicate point has its representative's cluster.
  std::vector<std::int32_t> label;
  std::size_t count = 0;
  std::vector<std::size_t> size;  ///< points per cluster (duplicates included)
  /// Seed rule only: the face-connected set of each simplex (−1: removed), and how many points
  /// lie on simplices of more than one set (such a point is labelled with the lowest set).
  std::vector<std::int32_t> simplex_set;
  std::size_t shared_points = 0;
};

/// The paper's rule. Points on no kept simplex form clusters of their own (the paper leaves them
/// out; here they are kept as single-point clusters so that every point has a label).
template <int N>
PointClusters seed_rule_clusters(const DelaunayDivision<N>& d, double critical_distance);

/// Single linkage through the Delaunay edges of length < critical_distance.
template <int N>
PointClusters single_linkage_clusters(const DelaunayDivision<N>& d, double critical_distance);

}  // namespace shockfield::geometry
