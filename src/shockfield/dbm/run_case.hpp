#pragma once
// `method = "dbm"`: the compressible BGK model as a plug-in of the run driver (core/method.hpp):
// validates the whole case file and steps it to end_time, writing domain means with the TNE
// strength (series.csv), line profiles along x with the TNE measures (profiles/), field frames
// (fields/, grid.pvd) and checkpoint.h5, from which --resume continues a stopped run bitwise.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::dbm {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);
/// A rank other than 0 of a decomposed run (docs/parallel.md): validates the case as rank 0 does
/// (the same InputError, so every rank exits 2 on bad input), then steps its block as rank 0 says.
void serve_ranks(const Config& root, const RunOptions& options);
/// Runs the case through the run driver.
void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::dbm
