#pragma once
// The one run loop of every method (method.hpp): validates the case through the method's factory
// (--check stops there), opens the run folder and its log, starts or resumes the method, steps it
// with the checkpoint schedule, the stop handlers and --stop-after, draws the progress line and
// the thermo table, and closes with the method's results and a performance summary. Exit codes
// through the exceptions the command line maps: InputError 2, RunError 3 (the outputs kept, a
// "run stopped" line in log.txt), StopRequested 130 (a checkpoint written).
#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield {

void run_method(const Config& root, const RunOptions& options, const MethodFactory& make_method);

}  // namespace shockfield
