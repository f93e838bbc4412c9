#pragma once
// The one run loop of every method (method.hpp): validates the case through the method's factory
// (--check stops there), opens the run folder and its log, starts or resumes the method, steps it
// with the checkpoint schedule, the stop handlers and --stop-after, draws the progress line and
// the thermo table, and closes with the method's results and a performance summary. Exit codes
// through the exceptions the command line maps: InputError 2, RunError 3 (the outputs kept, a
// "run stopped" line in log.txt), StopRequested 130 (a checkpoint written).
//
// run_method() is the command line's loop; RunDriver is the same run in pieces (open, step,
// finish) for a caller that steps the method itself: the Python module's in-process Simulation.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/core/run_summary.hpp"
#include "shockfield/core/run_thermo.hpp"

namespace shockfield {

void run_method(const Config& root, const RunOptions& options, const MethodFactory& make_method);

class RunDriver {
 public:
  /// Validates the case through the factory (InputError naming the case file).
  RunDriver(Config root, RunOptions options, const MethodFactory& make_method);
  RunDriver(const RunDriver&) = delete;
  RunDriver& operator=(const RunDriver&) = delete;

  /// Opens the run folder and starts (or resumes) the method; `stop_handlers`: Ctrl-C and
  /// SIGTERM stop the run with a checkpoint (the command line; an embedding program keeps its
  /// own). Returns false when a resumed run had nothing left to do (nothing more may be called).
  bool open(bool stop_handlers = true);
  bool finished() const { return method_->finished(); }
  /// One step with its outputs, thermo row, checkpoint schedule and stop checks.
  void step();
  /// The end of the run: final outputs, the last thermo row and checkpoint, results, summary.
  void finish();
  /// Stops the run here as Ctrl-C does (the stop state, a checkpoint, summary.json "stopped"),
  /// so that a run with the same options and `resume` continues it; returns the message saying
  /// how. Nothing more may be called.
  std::string stop();

  Method& method() { return *method_; }
  const Config& root() const { return root_; }
  const RunContext& context() const { return *run_; }

 private:
  using Clock = std::chrono::steady_clock;
  void save();
  void write_summary(const std::string& status, const std::string& message);

  const Config root_;
  const RunOptions options_;
  std::unique_ptr<Method> method_;
  std::optional<Provenance> provenance_;
  std::optional<RunSession> session_;
  std::optional<RunContext> run_;
  std::optional<RunThermo> thermo_;
  std::optional<Progress> progress_;
  RunTally tally_;
  Clock::time_point wall_start_;
  std::int64_t first_step_ = 0;
};

}  // namespace shockfield
