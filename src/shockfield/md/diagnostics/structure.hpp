#pragma once
// The in-run structure analysis of an MD case's [analysis] table: the same per-atom analyses as
// `shockfield analyze atoms` (analysis/atoms: adaptive and conventional CNA, centro-symmetry,
// coordination, bond pairs, defect clusters, the excess energy of the force evaluation's per-atom
// energies) on the simulation's own atoms, for structures.csv (step, time, atoms, counts and
// fractions per structure, the excess energy's reference and mean), clusters.csv (step, time, then
// the columns of analyze atoms' clusters.csv) and, optionally, the dump frames' columns.
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

class StructureDiagnostic {
 public:
  explicit StructureDiagnostic(const AnalysisSpec& spec);

  /// structures.csv: step, time_ps, atoms, then the count columns of analyze atoms.
  std::vector<std::string> columns() const;
  /// The analyses of the simulation's current atoms (with the excess energy: its forces were
  /// evaluated with per-atom energies, RunOutput::needs_per_atom).
  analysis::atoms::StructureAnalysisResult compute(const Simulation& sim) const;
  bool excess_energy() const { return static_cast<bool>(analyses_.excess_energy); }
  bool clusters() const { return analyses_.clusters.has_value(); }  ///< clusters.csv is written
  /// The structures.csv row of a result computed at the simulation's current step.
  std::vector<double> row(const Simulation& sim, const analysis::atoms::StructureAnalysisResult& r) const;

 private:
  analysis::atoms::ExcessEnergy excess_of(const Simulation& sim, const analysis::atoms::StructureAnalysisResult& r) const;

  analysis::atoms::StructureAnalyses analyses_;  ///< excess_energy: a marker, replaced per frame by excess_of
  std::optional<double> excess_reference_;       ///< eV; none: the median pe of the crystal's atoms
  analysis::atoms::Structure excess_crystal_ = analysis::atoms::Structure::fcc;
};

}  // namespace shockfield::md
