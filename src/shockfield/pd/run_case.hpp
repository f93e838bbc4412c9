#pragma once
// `method = "pd"`: peridynamics as a plug-in of the run driver (core/method.hpp): validates the
// whole case file, builds the body, its families and the force model, and runs velocity-Verlet
// to end_time with output, checkpoints and resume (a [homogeneous] case: homogeneous_case.hpp).
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::pd {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);
/// The ranks other than 0 of a run under mpirun (run_ranks.hpp): validate the case as rank 0
/// does, then make the calls rank 0 announces until the run ends.
void serve_ranks(const Config& root, const RunOptions& options);
/// Runs the case through the run driver.
void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::pd
