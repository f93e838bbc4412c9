#pragma once
// Coordination number, LAMMPS `compute coord/atom cutoff <r_c>` (all types): the number of
// neighbours (periodic images included) closer than r_c.
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"

namespace shockfield::analysis::atoms {

struct Coordination {
  double cutoff = 0;  ///< Å

  NeighborRequest request() const { return {cutoff, 0}; }
  std::vector<int> compute(const AtomFrame& frame, const NeighborTable& table) const;
};

/// Neighbours of atom i closer than sqrt(cutoff2) (the table's lists are sorted: a prefix).
std::size_t neighbors_within(const NeighborTable& table, std::size_t i, double cutoff2);

}  // namespace shockfield::analysis::atoms
