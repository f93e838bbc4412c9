#pragma once
// The one neighbour pass every structure analysis shares. For each atom, its neighbours sorted by
// distance (ties by owner index), built from geometry/'s cell-list neighbour search over the
// atoms and their periodic images (md/ghosts, LAMMPS semantics). Two requests combine:
//   cutoff         every neighbour closer than it is listed (coordination, conventional CNA);
//   min_neighbors  at least this many nearest neighbours are listed (adaptive CNA, CSP): an atom
//                  with fewer within the cutoff is searched again with the cutoff doubled, up to
//                  kMaxWidenings times or until the cutoff exceeds the box diagonal.
// The list of atom i is complete out to reach(i) (>= cutoff): no closer atom is missing.
// Neighbours are entries of points(): the atoms (wrapped into the periodic box) then ghost
// images; owner() maps an entry back to its atom. Independent of the thread count.
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/core/uninitialized_vector.hpp"

namespace shockfield::analysis::atoms {

struct NeighborRequest {
  double cutoff = 0;      ///< Å; 0: only min_neighbors decides
  int min_neighbors = 0;  ///< nearest neighbours wanted per atom

  /// The request that satisfies both.
  NeighborRequest combined(const NeighborRequest& other) const;
};

class NeighborTable {
 public:
  static constexpr int kMaxWidenings = 6;

  NeighborTable(const AtomFrame& frame, const NeighborRequest& request);

  std::size_t size() const { return nlocal_; }
  const NeighborRequest& request() const { return request_; }
  /// Throws std::invalid_argument naming `analysis` when the table was built for less than `r`.
  void require(const NeighborRequest& r, std::string_view analysis) const;
  /// Entries of atom i's neighbours, nearest first.
  std::span<const int> of(std::size_t i) const {
    return {neighbors_.data() + offset_[i], static_cast<std::size_t>(offset_[i + 1] - offset_[i])};
  }
  /// Separation vector from atom i to entry j (x_j − x_i, Å).
  Vec3 delta(std::size_t i, int j) const { return points_[static_cast<std::size_t>(j)] - points_[i]; }
  /// The atom (0-based frame index) an entry is, or an image of.
  int owner(int j) const { return j < static_cast<int>(nlocal_) ? j : ghost_owner_[static_cast<std::size_t>(j) - nlocal_]; }
  /// Radius out to which atom i's list holds every neighbour, Å.
  double reach(std::size_t i) const { return reach_[i]; }
  std::size_t entries() const { return neighbors_.size(); }
  /// Bytes held by the table (for benchmarks).
  std::size_t memory_bytes() const;

 private:
  /// Nearest first; ties (exact in perfect lattices) by owner, then by entry, so the order
  /// depends on the positions only.
  void sort_nearest(std::vector<std::pair<double, int>>& found) const;
  /// Atoms with fewer neighbours than requested (`lists` empty: none widened yet).
  std::vector<std::size_t> atoms_short_of_request(const std::vector<std::vector<int>>& lists) const;
  /// Lists the short atoms again with a wider cutoff (new ghosts become entries).
  void widen(const AtomFrame& frame, const std::vector<std::size_t>& short_atoms,
             std::vector<std::vector<int>>& lists, double cutoff);

  NeighborRequest request_;
  std::size_t nlocal_ = 0;
  std::vector<Vec3> points_;
  std::vector<int> ghost_owner_;
  UninitializedVector<std::int64_t> offset_;  // the neighbour list's arrays, moved in
  UninitializedVector<int> neighbors_;
  std::vector<double> reach_;
};

/// A cutoff that holds about `count` neighbours at the frame's mean density (box volume / atoms),
/// with 10% margin: the first search radius for a min_neighbors request.
double density_cutoff(const AtomFrame& frame, int count);

}  // namespace shockfield::analysis::atoms
