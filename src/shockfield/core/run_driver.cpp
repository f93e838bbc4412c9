#include "shockfield/core/run_driver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/core/run_thermo.hpp"

namespace shockfield {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Wall time of the driver's phases over this session.
struct Timers {
  double step = 0.0, output = 0.0, checkpoint = 0.0;
};

void log_performance(Logger& log, const Method& m, std::int64_t steps, double wall, const Timers& t) {
  const double rate = wall > 0 ? static_cast<double>(steps) / wall : 0.0;
  std::string line = fmt::format("performance: {} steps in {} ({:.4g} steps/s, {:.4g} {}-steps/s", steps,
                                 format_duration(wall), rate, rate * m.work_items(), m.work_item_name());
  if (m.ns_per_step() > 0) line += fmt::format(", {:.4g} ns/day", rate * m.ns_per_step() * 86400.0);
  log.line(line + ")");
  std::string phases = fmt::format("wall time: step {:.3g} s", t.step);
  for (const PhaseTime& p : m.phase_times()) phases += fmt::format(" (of which {} {:.3g} s)", p.name, p.seconds);
  phases += fmt::format(", output {:.3g} s, checkpoint {:.3g} s, other {:.3g} s", t.output, t.checkpoint,
                        std::max(0.0, wall - t.step - t.output - t.checkpoint));
  log.line(phases);
}

}  // namespace

void run_method(const Config& root, const RunOptions& options, const MethodFactory& make_method) {
  std::unique_ptr<Method> method = make_method(root, options);
  Method& m = *method;
  if (options.validate_only) {
    std::printf("%s: valid %s\n", options.case_file.string().c_str(), m.check_text().c_str());
    return;
  }
  RunSession session = open_run_session(root, options, m.name(), m.size_text());
  RunContext run{session.folder, session.checkpoint, session.log, options};
  Logger& log = session.log;
  const Clock::time_point wall_start = Clock::now();
  if (options.resume) {
    if (!fs::exists(run.checkpoint))
      throw InputError(fmt::format("--resume: no checkpoint in '{}'", run.folder.string()));
    m.resume(run);
    log.info("resumed from {} at step {}{}", run.checkpoint.string(), m.step(), m.position());
    if (m.finished()) {
      log.info("nothing to do: the run was finished at step {}{}", m.step(), m.position());
      return;
    }
  } else {
    m.start(run);
  }
  RunThermo thermo(run, m);

  clear_stop_request();
  install_stop_handlers();
  const std::int64_t first = m.step();
  Progress progress(m.name(), first, m.steps_left(), !options.quiet);
  Timers timers;
  const auto save = [&] {
    const Clock::time_point t0 = Clock::now();
    m.write_checkpoint(run.checkpoint);
    timers.checkpoint += seconds_since(t0);
  };
  try {
    while (!m.finished()) {
      Clock::time_point t0 = Clock::now();
      m.advance();
      m.check_health();
      timers.step += seconds_since(t0);
      t0 = Clock::now();
      m.write_outputs();
      thermo.at_step();
      timers.output += seconds_since(t0);
      const std::int64_t step = m.step();
      if (m.checkpoint_every() > 0 && step % m.checkpoint_every() == 0) save();
      progress.update(step, m.fraction_done());
      if (stop_requested() || (options.stop_after > 0 && step - first == options.stop_after)) {
        progress.finish(step);
        const std::string wrote = m.write_stop_state();
        save();
        log.info("stopped at step {}{}: checkpoint written to {}{}", step, m.position(), run.checkpoint.string(),
                 wrote.empty() ? "" : ", " + wrote);
        throw StopRequested(fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                        step, options.case_file.string(), run.folder.string()));
      }
    }
  } catch (const RunError& e) {
    log.info("run stopped: {}", e.what());
    const std::string wrote = m.write_failure_state();
    log.info("the output written so far is kept in {}{}", run.folder.string(), wrote.empty() ? "" : "; " + wrote);
    throw;
  }
  progress.finish(m.step());
  m.write_final_outputs();
  thermo.at_end();
  save();
  const double wall = seconds_since(wall_start);
  m.log_results(progress.rate(m.step()));
  log_performance(log, m, m.step() - first, wall, timers);
}

}  // namespace shockfield
