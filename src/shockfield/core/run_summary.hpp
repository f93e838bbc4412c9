#pragma once
// summary.json of a run folder (docs/summary-json.md): the common part the run driver knows (method,
// case, status, steps, time, wall time, rates, phases, provenance) and the method's results.
// Written however the run ends: finished, stopped or failed.
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/core/method.hpp"
#include "shockfield/core/provenance.hpp"

namespace shockfield {

struct RunTally {
  std::int64_t steps = 0;        ///< steps of this session (for the rates)
  double wall_seconds = 0.0;     ///< this session
  double step_seconds = 0.0, output_seconds = 0.0, checkpoint_seconds = 0.0;
};

/// `status`: "finished", "stopped" or "failed"; `message` why (empty when finished).
void write_run_summary(const std::filesystem::path& folder, const std::filesystem::path& case_file, const Method& m,
                       const std::string& status, const std::string& message, const RunTally& tally,
                       const Provenance& provenance);

/// The provenance as summary.json writes it (the fields of [provenance]).
Json provenance_json(const Provenance& provenance);

}  // namespace shockfield
