#pragma once
// `method = "mpm"`: the material point method as a plug-in of the run driver (core/method.hpp):
// validates the whole case file, builds the sample and runs to end_time with its diagnostics
// and output.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::mpm {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);
/// Runs the case through the run driver.
void run_case(const Config& root, const RunOptions& options);

}  // namespace shockfield::mpm
