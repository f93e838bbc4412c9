#pragma once
// What an MD run writes while it runs: thermo.csv (one row every thermo_every steps),
// profiles.csv (binned profiles every profile_every steps), structures.csv (the [analysis]
// table's structure fractions every `every` steps), dumps/ (one file per frame, LAMMPS
// text dump or extended XYZ, so a resumed run simply removes frames past its checkpoint; OVITO
// opens the series as dumps/dump.*.lammpstrj), trajectory.h5md (H5MD, every h5md_every steps, atoms in
// id order: MDAnalysis and VMD read it; a resumed run cuts it back to its checkpoint). Rows and
// frames are flushed when written.
// A run decomposed over MPI ranks (sim.domain) has a RunOutput on every rank making the same
// decisions: the thermo sums and the dump's gather are collective, and only rank 0 (`writes`)
// has files. Profiles, [analysis], H5MD and per-atom energy or stress columns are not decomposed
// (refused before such a run).
#include <filesystem>
#include <optional>

#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/h5md_writer.hpp"
#include "shockfield/md/diagnostics/structure.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

class RunOutput {
 public:
  /// `resume_step`: a resumed run keeps rows and frames up to that step and rewrites the rest.
  /// `writes`: false on the ranks other than 0 of a decomposed run (no file is touched).
  RunOutput(const std::filesystem::path& folder, const OutputSpec& spec,
            std::optional<std::int64_t> resume_step, bool writes = true);

  /// Whether step `step` writes something that needs per-atom energies and virials.
  bool needs_per_atom(std::int64_t step) const;
  /// Writes whatever is due at the simulation's current step.
  void write(const Simulation& sim, bool force_thermo = false);

  const std::filesystem::path& profiles_file() const { return profiles_file_; }

 private:
  void write_thermo(const Simulation& sim);
  /// `analysed`: the [analysis] result of this step, appended as columns (dump_columns), or null.
  /// `atoms`: the simulation's, or of a decomposed run every rank's gathered on rank 0.
  void write_dump(const Simulation& sim, const Atoms& atoms, const analysis::atoms::StructureAnalysisResult* analysed) const;
  bool dump_needs_per_atom() const;
  void write_h5md(const Simulation& sim);

  std::filesystem::path folder_, profiles_file_;
  OutputSpec spec_;
  io::CsvWriter thermo_, profiles_, structures_, clusters_;
  std::optional<StructureDiagnostic> structure_;  ///< the [analysis] table, when the case has one
  std::optional<io::H5mdWriter> h5md_;            ///< opened at its first frame (the atom count known)
  std::optional<std::int64_t> resume_step_;
  bool writes_ = true;
  std::int64_t last_thermo_step_ = -1, last_frame_step_ = -1;
};

}  // namespace shockfield::md
