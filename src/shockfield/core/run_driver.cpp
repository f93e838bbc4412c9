#include "shockfield/core/run_driver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "shockfield/core/case_diff.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/core/run_summary.hpp"
#include "shockfield/core/run_thermo.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// --resume: the changes between the case stored in the checkpoint (`case_input`, the case as read
// by the run that wrote it) and the one given; refused (InputError listing every changed key)
// unless all are in the method's safe list. Without a checkpoint the run refuses later, by name.
std::vector<CaseChange> check_resume_case(const Config& root, const RunOptions& options, const Method& m) {
  const fs::path checkpoint = run_session_checkpoint(run_folder_path(options));
  if (!fs::exists(checkpoint)) return {};
  const std::string stored = checkpoint.string() + " (its case_input)";
  std::vector<CaseChange> changes = diff_cases(io::CheckpointReader(checkpoint).input_case(), root.case_toml(), stored);
  const std::vector<std::string> safe = m.resume_safe_keys();
  const auto is_safe = [&](const CaseChange& c) {
    return std::any_of(safe.begin(), safe.end(), [&](const std::string& p) { return key_matches(c.key, p); });
  };
  if (std::all_of(changes.begin(), changes.end(), is_safe)) return changes;
  std::string list, allowed;
  for (const CaseChange& c : changes)
    list += fmt::format("\n  {}: {} -> {}{}", c.key, c.before, c.after, is_safe(c) ? " (safe)" : "");
  for (const std::string& p : safe) allowed += (allowed.empty() ? "" : ", ") + p;
  throw InputError(fmt::format("--resume: the case differs from the one the checkpoint was written with ({}) in "
                               "keys a resumed run cannot change:{}\nsafe to change on resume: {}; undo the edit, "
                               "or start a new run with --overwrite or --output",
                               stored, list, allowed));
}

// --resume: an input file (potential, material file, data) whose SHA-256 differs from the one
// the run's config.resolved.toml recorded when it started is refused like a changed case key.
void check_resume_inputs(const RunOptions& options, const Provenance& now) {
  const fs::path resolved = run_folder_path(options) / "config.resolved.toml";
  if (!fs::exists(resolved)) return;
  toml::table before;
  try {
    before = toml::parse_file(resolved.string());
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("--resume: {} is not TOML ({}); start a new run with --overwrite or --output",
                                 resolved.string(), e.description()));
  }
  const toml::array* files = before.at_path("provenance.input_files").as_array();
  if (!files) return;
  for (const InputFileRecord& f : now.input_files)
    for (const toml::node& n : *files) {
      const toml::table* t = n.as_table();
      if (!t || t->at_path("path").value_or(std::string()) != f.path) continue;
      const std::string hash = t->at_path("sha256").value_or(std::string());
      if (hash != f.sha256)
        throw InputError(fmt::format("--resume: input file {} changed since the run started (sha256 {} in {}, now "
                                     "{}); restore it, or start a new run with --overwrite or --output",
                                     f.path, hash, resolved.string(), f.sha256));
    }
}

void log_performance(Logger& log, const Method& m, const RunTally& t) {
  const double rate = t.wall_seconds > 0 ? static_cast<double>(t.steps) / t.wall_seconds : 0.0;
  std::string line = fmt::format("performance: {} steps in {} ({:.4g} steps/s, {:.4g} {}-steps/s", t.steps,
                                 format_duration(t.wall_seconds), rate, rate * m.work_items(), m.work_item_name());
  if (m.ns_per_step() > 0) line += fmt::format(", {:.4g} ns/day", rate * m.ns_per_step() * 86400.0);
  log.line(line + ")");
  std::string phases = fmt::format("wall time: step {:.3g} s", t.step_seconds);
  const std::vector<PhaseTime> parts = m.phase_times();
  for (std::size_t k = 0; k < parts.size(); ++k)
    phases += fmt::format("{}{} {:.3g} s{}", k == 0 ? " (of which " : ", ", parts[k].name, parts[k].seconds,
                          k + 1 == parts.size() ? ")" : "");
  phases += fmt::format(", output {:.3g} s, checkpoint {:.3g} s, other {:.3g} s", t.output_seconds,
                        t.checkpoint_seconds,
                        std::max(0.0, t.wall_seconds - t.step_seconds - t.output_seconds - t.checkpoint_seconds));
  log.line(phases);
}

// The method's factory, its InputErrors naming the case file: a check made while building the
// system (a body outside its box, an unknown group) may not know which file the values came from.
std::unique_ptr<Method> make_checked(const Config& root, const RunOptions& options, const MethodFactory& make_method) {
  try {
    return make_method(root, options);
  } catch (const InputError& e) {
    const std::string file = std::filesystem::path(root.file()).filename().string();
    if (file.empty() || std::string_view(e.what()).find(file) != std::string_view::npos) throw;
    throw InputError(fmt::format("{}: {}", root.file(), e.what()));
  }
}

}  // namespace

RunDriver::RunDriver(Config root, RunOptions options, const MethodFactory& make_method)
    : root_(std::move(root)), options_(std::move(options)), method_(make_checked(root_, options_, make_method)) {
  root_.check_replayed_derived();
}

bool RunDriver::open(bool stop_handlers) {
  Method& m = *method_;
  const std::vector<CaseChange> changes =
      options_.resume ? check_resume_case(root_, options_, m) : std::vector<CaseChange>{};
  provenance_ = collect_provenance(options_.command_line, root_.input_files());
  if (options_.resume) check_resume_inputs(options_, *provenance_);
  root_.set_provenance(provenance_toml(*provenance_));
  session_.emplace(open_run_session(root_, options_, m.name(), m.size_text(), provenance_lines(*provenance_),
                                    !changes.empty()));
  run_.emplace(RunContext{session_->folder, session_->checkpoint, session_->log, options_});
  for (const CaseChange& c : changes)
    run_->log.info("resume: {} changed from {} to {} (a safe change; config.resolved.toml rewritten)", c.key,
                   c.before, c.after);
  wall_start_ = Clock::now();
  if (options_.resume) {
    if (!fs::exists(run_->checkpoint))
      throw InputError(fmt::format("--resume: no checkpoint in '{}'", run_->folder.string()));
    m.resume(*run_);
    run_->log.info("resumed from {} at step {}{}", run_->checkpoint.string(), m.step(), m.position());
    if (m.finished()) {
      run_->log.info("nothing to do: the run was finished at step {}{}", m.step(), m.position());
      return false;
    }
  } else {
    m.start(*run_);
  }
  thermo_.emplace(*run_, m);
  clear_stop_request();
  if (stop_handlers) install_stop_handlers();
  first_step_ = m.step();
  progress_.emplace(m.name(), first_step_, m.steps_left(), !options_.quiet);
  return true;
}

void RunDriver::save() {
  const Clock::time_point t0 = Clock::now();
  {
    const io::CheckpointCaseScope stored_case({root_.resolved_toml(), root_.case_toml()});
    method_->write_checkpoint(run_->checkpoint);
  }
  tally_.checkpoint_seconds += seconds_since(t0);
}

void RunDriver::write_summary(const std::string& status, const std::string& message) {
  tally_.wall_seconds = seconds_since(wall_start_);
  provenance_->end_time = iso8601_utc_now();
  write_run_summary(run_->folder, options_.case_file, *method_, status, message, tally_, *provenance_);
}

void RunDriver::step() {
  Method& m = *method_;
  try {
    Clock::time_point t0 = Clock::now();
    m.advance();
    m.check_health();
    tally_.step_seconds += seconds_since(t0);
    t0 = Clock::now();
    m.write_outputs();
    thermo_->at_step();
    tally_.output_seconds += seconds_since(t0);
    const std::int64_t step = m.step();
    tally_.steps = step - first_step_;
    if (m.checkpoint_every() > 0 && step % m.checkpoint_every() == 0) save();
    progress_->update(step, m.fraction_done());
    if (stop_requested() || (options_.stop_after > 0 && step - first_step_ == options_.stop_after))
      throw StopRequested(stop());
  } catch (const RunError& e) {
    // Reporting the failure writes too (log.txt, the failure state, summary.json); on a full disk
    // that fails as well, and must not hide the error that stopped the run.
    try {
      run_->log.info("run stopped: {}", e.what());
      const std::string wrote = m.write_failure_state();
      run_->log.info("the output written so far is kept in {}{}", run_->folder.string(),
                     wrote.empty() ? "" : "; " + wrote);
      write_summary("failed", e.what());
    } catch (const RunError& reporting) {
      throw RunError(fmt::format("{} (then, saving the failure state: {})", e.what(), reporting.what()));
    }
    throw;
  }
}

std::string RunDriver::stop() {
  Method& m = *method_;
  const std::int64_t step = m.step();
  progress_->finish(step);
  const std::string wrote = m.write_stop_state();
  save();
  run_->log.info("stopped at step {}{}: checkpoint written to {}{}", step, m.position(), run_->checkpoint.string(),
                 wrote.empty() ? "" : ", " + wrote);
  const std::string message = fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                          step, options_.case_file.string(), run_->folder.string());
  write_summary("stopped", message);
  return message;
}

void RunDriver::finish() {
  Method& m = *method_;
  progress_->finish(m.step());
  m.write_final_outputs();
  thermo_->at_end();
  save();
  tally_.wall_seconds = seconds_since(wall_start_);
  m.log_results(progress_->rate(m.step()));
  log_performance(run_->log, m, tally_);
  write_summary("finished", "");
}

void run_method(const Config& root, const RunOptions& options, const MethodFactory& make_method) {
  RunDriver driver(root, options, make_method);
  if (options.validate_only) {
    std::printf("%s: valid %s\n", options.case_file.string().c_str(), driver.method().check_text().c_str());
    return;
  }
  if (!driver.open()) return;
  while (!driver.finished()) driver.step();
  driver.finish();
}

}  // namespace shockfield
