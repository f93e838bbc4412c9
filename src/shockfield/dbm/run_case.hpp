#pragma once
// `shockfield run` for method = "dbm": validate the whole case file, create the run folder and
// step the compressible BGK model to end_time, writing domain means with the TNE strength
// (series.csv), line profiles along x with the TNE measures (profiles/), field frames (fields/,
// grid.pvd) and checkpoint.h5, from which --resume continues a stopped run bitwise.
#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::dbm {

void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::dbm
