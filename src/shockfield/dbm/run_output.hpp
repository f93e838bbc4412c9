#pragma once
// What a `method = "dbm"` run writes while it runs: series.csv (domain means with the TNE
// strength, or the GLS columns, plus the reactive columns of a [reaction] case), profiles/ (line
// profiles along x at row profile_row with the TNE measures, indexed by profiles/index.csv) and
// fields/ with grid.pvd. A resumed run keeps what was written up to its checkpoint and rewrites
// the rest.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/checkpoint.hpp"
#include "shockfield/dbm/gls_run.hpp"
#include "shockfield/dbm/reaction.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::dbm {

class RunOutput {
 public:
  /// `resumed`: the simulation restored from a checkpoint with `counters`, or null for a fresh
  /// run; `reaction`: the reactive DBM of a [reaction] case (extra columns), or null; `gls`: the
  /// liquid–vapour part of a kind = "gls" case (its own series columns), or null.
  RunOutput(const std::filesystem::path& folder, const DbmOutputSpec& spec, const Simulation* resumed,
            const OutputCounters& counters, const ReactiveFlow* reaction,
            const std::optional<ReactionSpec>& spec_reaction, GlsRunPart* gls);

  void write_series(const Simulation& sim);
  /// profiles/profile_<index>.csv and its row in profiles/index.csv.
  void write_profile(const Simulation& sim, std::int64_t index);
  /// ρ, u, T and the TNE strength D (or the GLS fields) on the cell centres.
  void write_fields(const Simulation& sim);

 private:
  std::filesystem::path folder_;
  int row_;
  io::VtkFormat vtk_;
  const ReactiveFlow* reaction_;
  const std::optional<ReactionSpec>& spec_reaction_;
  GlsRunPart* gls_;
  io::CsvWriter series_, index_;
  io::PvdSeries grid_pvd_;
};

}  // namespace shockfield::dbm
