#pragma once
// `shockfield run` for method = "dbm": validate the whole case file, create the run folder and
// step the compressible BGK model to end_time, writing domain means with the TNE strength
// (series.csv) and line profiles along x with the TNE measures (profiles/). No checkpoints yet:
// a stopped run keeps its output but cannot be resumed.
#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::dbm {

void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::dbm
