#pragma once
// `shockfield run` for method = "mpm": validate the whole case file, build the sample, create the
// run folder and run the material point method to end_time with its diagnostics and output.
#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::mpm {

void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::mpm
