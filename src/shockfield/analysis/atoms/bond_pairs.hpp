#pragma once
// Bond-pair analysis, Honeycutt & Andersen, J. Phys. Chem. 91, 4950 (1987): every pair of atoms
// closer than the cutoff is a bond, labelled by four digits 1jkl — 1: the pair is bonded, j: its
// common neighbours, k: bonds among them, l: which arrangement of those bonds (here 2 for two
// bonds sharing an atom, 1422, and 1 otherwise; the full triple (j, k, longest chain) is kept, so
// nothing is lost where one digit cannot tell arrangements apart). Ideal structures at a cutoff
// between their bonded and unbonded shells: fcc 12 × 1421; hcp 6 × 1421 + 6 × 1422;
// bcc (cutoff past the second shell) 8 × 1661 + 6 × 1441; icosahedron centre 12 × 1551.
// An atom's type from its bonds is that structure when its bonds are exactly one of those sets,
// otherwise other.
#include <cstdint>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/common_neighbors.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"
#include "shockfield/analysis/atoms/structure_types.hpp"

namespace shockfield::analysis::atoms {

/// The four-digit index of a bond signature; 0 when j or k exceed 9 (no four-digit label).
int honeycutt_andersen_index(const BondSignature& s);

struct BondPairResult {
  /// Per atom its bonds (CSR over atoms, frame order): the bonded entry (NeighborTable::owner()
  /// gives the atom) and the index, nearest bond first.
  std::vector<std::int64_t> offset;
  std::vector<int> partner;  ///< atom index of the bonded neighbour
  std::vector<int> index;    ///< Honeycutt–Andersen index of the bond
  std::vector<Structure> structure;
  StructureCounts counts;
};

struct BondPairAnalysis {
  double cutoff = 0;  ///< Å, the bond length criterion

  NeighborRequest request() const { return {cutoff, 0}; }
  /// Throws InputError for a cutoff <= 0, or naming the atom that has more than kMaxNeighbors bonds.
  BondPairResult compute(const AtomFrame& frame, const NeighborTable& table) const;
};

}  // namespace shockfield::analysis::atoms
