#pragma once
// How structure-analysis results are written, the same for `shockfield analyze atoms` and for an
// MD run's in-run [analysis]: per-atom dump columns (coord, cna, acna, csp, bpa, cluster; OVITO
// colours by them) and the counts and fractions per structure of a frame (structures.csv).
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::analysis::atoms {

/// Appends the per-atom results to the dump frame as columns coord, cna, acna, csp, bpa (codes
/// 1 fcc ... 5 other), dia (OVITO's diamond codes 0-6), cluster (1, 2, ... largest first; 0
/// none) and excess (eV). `natoms` = the frame's atoms.
void append_structure_columns(io::DumpFrame& dump, const StructureAnalysisResult& r, std::size_t natoms);

/// The count columns of structures.csv for the structure methods asked for, in the order cna,
/// acna, bpa, dia: <method>_<structure>_count for each structure, then <method>_<structure>_fraction
/// (pure numbers, docs/conventions.md; dia: cubic, cubic_first, cubic_second, hexagonal,
/// hexagonal_first, hexagonal_second, other);
/// with an excess energy, then excess_reference_eV (e0) and excess_mean_eV (over all atoms).
std::vector<std::string> structure_count_columns(const StructureAnalyses& analyses);
/// Their values for one frame's result (the same order).
std::vector<double> structure_count_values(const StructureAnalysisResult& r);

}  // namespace shockfield::analysis::atoms
