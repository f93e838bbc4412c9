#pragma once
// `shockfield run` for method = "pd": validate the whole case file, build the body, its families
// and the force model, create the run folder and run velocity-Verlet to end_time with output,
// checkpoints and resume.
#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::pd {

void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::pd
