#pragma once
// Verlet neighbour list in CSR form, built from a cell list. A *half* list holds each pair once
// (Newton's third law is applied by the force kernel): a pair of owned points (i < j) is kept by
// i; a pair of an owned point i and a ghost j is kept when j lies "above" i (larger z, then y,
// then x), so of the two periodic copies of a pair that crosses a face exactly one is kept.
// A *full* list holds each owned point's every neighbour. Each point's neighbours are in stencil
// order (nearby bins, then point index), which depends on the positions only.
#include <cstdint>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/core/uninitialized_vector.hpp"

namespace shockfield::geometry {

struct NeighborList {
  // Filled by all threads: a resize must not zero them on one thread first.
  UninitializedVector<std::int64_t> offset;  ///< size nlocal + 1
  UninitializedVector<int> neighbors;        ///< neighbour indices into the point array (owned or ghost)
  double cutoff = 0;                 ///< list cutoff (force cutoff + skin)
  bool half = true;

  std::size_t nlocal() const { return offset.empty() ? 0 : offset.size() - 1; }
  std::size_t pairs() const { return neighbors.size(); }
};

/// Builds the list for points[0, nlocal) against all points (owned and ghosts) within `cutoff`.
/// Threads (OpenMP) split the owned points; the result does not depend on the thread count.
void build_neighbor_list(const std::vector<Vec3>& points, std::size_t nlocal, double cutoff,
                         bool half, NeighborList& list);

}  // namespace shockfield::geometry
