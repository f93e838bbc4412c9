#pragma once
// `method = "granular"`: the Hertzian chain (simulation.hpp) as a plug-in of the run driver
// (core/method.hpp): validates the whole case file, steps the chain with velocity Verlet to
// end_time, writes series.csv, probes.csv, the space–time fields and signal.csv (outputs.hpp) and
// checkpoint.h5, from which --resume continues a stopped run bitwise.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::granular {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);

}  // namespace shockfield::granular
