#pragma once
// Centro-symmetry parameter, Kelchner, Plimpton & Hamilton, Phys. Rev. B 58, 11085 (1998), with
// the pairing of LAMMPS `compute centro/atom` (its default, without `axes`):
//   CSP_i = Σ of the N/2 smallest of |R_j + R_k|² over all N(N−1)/2 pairs j < k of the N nearest
//           neighbours of i (R: vectors from i),
// N = 12 for fcc, 8 for bcc, or any even N. 0 for a perfect centro-symmetric site, a² scale for a
// surface atom (Å²). As in LAMMPS, an atom with fewer than N neighbours gets 0. LAMMPS looks for
// the N nearest only within the pair-style cutoff; here they are the N nearest, wherever they
// are, so the two differ only for atoms with fewer than N neighbours inside that cutoff.
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"

namespace shockfield::analysis::atoms {

struct CentroSymmetry {
  int neighbors = 12;  ///< N: 12 fcc, 8 bcc; even, 2..kMaxNeighbors

  /// N from "fcc", "bcc" or a number; throws InputError naming `what` otherwise.
  static int parse_neighbors(const std::string& text, const std::string& what);

  NeighborRequest request() const { return {0, neighbors}; }
  /// CSP per atom (Å²), frame order.
  std::vector<double> compute(const AtomFrame& frame, const NeighborTable& table) const;
};

}  // namespace shockfield::analysis::atoms
