#pragma once
// `method = "md"`: reads and validates an MD case file, builds the system, runs the stages it
// lists and writes the run folder.
#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::md {

void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::md
