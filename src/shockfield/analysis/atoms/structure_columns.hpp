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

// The columns of analyze atoms' tables after frame and timestep, the same for the CSV files and
// the Python dicts (python/src/atoms_bindings.cpp); lengths, areas, volumes and energies carry
// their metal unit (_A, _A2, _A3, _eV; docs/conventions.md), indices, counts, unit vectors and
// flags none.
/// profiles.csv: bin, lo_A, hi_A, centre_A, atoms, <method>_<structure>_fraction for each method
/// given, then mean_excess_eV with an excess energy.
std::vector<std::string> profile_columns(const std::vector<std::string>& methods, bool excess);
/// domains.csv: domain, atoms, volume_A3, area_A2, equivalent_radius_A, atoms_volume_A3,
/// atoms_radius_A, x_A, y_A, z_A, euler_characteristic, manifold.
std::vector<std::string> domain_columns();
/// voids.csv: void, cells, volume_A3, area_A2, equivalent_radius_A, missing_volume_A3,
/// missing_radius_A, x_A, y_A, z_A, surface_atoms, euler_characteristic, manifold.
std::vector<std::string> void_columns();
/// burgers.csv: circuit, source (text), atoms, centre_x_A ... centre_z_A, axis_x ... axis_z (a unit
/// vector), radius_A, b (text), kind (text), b_h6, b_k6, b_l6 (b in a/6, crystal axes), bx_A, by_A,
/// bz_A (box axes), max_step_error (in nearest-neighbour distances), reliable (0/1).
std::vector<std::string> burgers_columns();
/// The text columns among them (burgers.csv's source, b, kind).
bool is_text_column(const std::string& name);
/// "frame,timestep," then the columns joined by commas, and a newline: a CSV header.
std::string csv_header(const std::vector<std::string>& columns);

}  // namespace shockfield::analysis::atoms
