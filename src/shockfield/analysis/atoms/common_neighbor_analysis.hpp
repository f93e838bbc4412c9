#pragma once
// Per-atom structure by common-neighbour analysis, two forms over the shared NeighborTable.
//
// ConventionalCna — LAMMPS `compute cna/atom <cutoff>` (Faken & Jónsson 1994; Tsuzuki et al.
// 2007): the neighbours closer than the cutoff are the bonded set. An atom with 12 of them is fcc
// when all 12 bonds have signature (common, bonds, max_bond, min_bond) = (4,2,1,1), hcp when 6
// have (4,2,1,1) and 6 (4,2,2,0), icosahedral when all 12 have (5,5,2,2); an atom with 14 is bcc
// when 6 have (4,4,2,2) and 8 (6,6,2,2); any other atom, or count, is "other". Cutoffs that work:
// fcc ½(1/√2 + 1)·a = 0.854 a, bcc ½(1 + √2)·a = 1.207 a (LAMMPS docs).
//
// AdaptiveCna — Stukowski, Modelling Simul. Mater. Sci. Eng. 20, 045021 (2012), no cutoff: the
// 12 nearest neighbours with the local cutoff r_c = (1+√2)/2 · (1/12) Σ_{j≤12} r_j give fcc when all
// 12 bonds are (common, bonds, chain) = (4,2,1), hcp when 6 are (4,2,1) and 6 (4,2,2), ico when
// all 12 are (5,5,5); otherwise the 14 nearest with r_c = (1+√2)/2 · (2/√3 Σ_{j≤8} r_j + Σ_{9≤j≤14} r_j)/14
// give bcc when 8 bonds are (6,6,6) and 6 are (4,4,4); otherwise "other". Scale-free: the same
// answer at any lattice constant and under moderate homogeneous strain.
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"
#include "shockfield/analysis/atoms/structure_types.hpp"

namespace shockfield::analysis::atoms {

struct StructureResult {
  std::vector<Structure> structure;  ///< per atom, frame order
  StructureCounts counts;
};

struct ConventionalCna {
  double cutoff = 0;  ///< Å, between the neighbour shells that make the structure's bonded set

  NeighborRequest request() const { return {cutoff, 0}; }
  /// Throws InputError unless cutoff > 0 and the table lists every neighbour within it.
  StructureResult compute(const AtomFrame& frame, const NeighborTable& table) const;
};

struct AdaptiveCna {
  NeighborRequest request() const { return {0, 14}; }
  StructureResult compute(const AtomFrame& frame, const NeighborTable& table) const;
};

}  // namespace shockfield::analysis::atoms
