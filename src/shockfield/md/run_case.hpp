#pragma once
// `method = "md"`: molecular dynamics as a plug-in of the run driver (core/method.hpp): reads and
// validates an MD case file, builds the system and runs the stages it lists.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::md {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);
/// The ranks other than 0 of `shockfield run` under mpirun: their part of the decomposed run
/// (run_ranks.hpp), driven by rank 0 until the run ends.
void serve_ranks(const Config& root, const RunOptions& options);
/// Runs the case through the run driver.
void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::md
