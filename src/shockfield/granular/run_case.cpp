#include "shockfield/granular/run_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "shockfield/core/json.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/state_array.hpp"
#include "shockfield/granular/case_file.hpp"
#include "shockfield/granular/checkpoint.hpp"
#include "shockfield/granular/outputs.hpp"

namespace shockfield::granular {

namespace fs = std::filesystem;

namespace {

// The health check (non-finite values, a contact stiffer than the step allows) costs about a
// step (a square root per contact), so it runs every kHealthEvery steps and on the last one.
constexpr long long kHealthEvery = 64;

// The chain as a plug-in of the run driver: a fixed step, ceil(end_time / dt) steps (the last
// one may pass end_time by less than a step), rows due at k·interval written at the first step
// at or past it (outputs.hpp).
class GranularMethod final : public Method {
 public:
  explicit GranularMethod(const GranularCase& c)
      : c_(c), sim_(build_simulation(c_)), steps_(static_cast<long long>(std::ceil(c_.run.end_time / sim_.time_step()))),
        initial_total_(sim_.thermo().total) {}

  std::string name() const override { return "granular"; }
  std::string size_text() const override { return fmt::format("{} grains", sim_.size()); }
  std::string check_text() const override {
    return fmt::format("granular case ({} grains, {} steps of {:.3g} s)", sim_.size(), steps_, sim_.time_step());
  }

  void start(RunContext& run) override {
    open(run, nullptr);
    write_outputs();
  }
  void resume(RunContext& run) override {
    counters_ = read_checkpoint(run.checkpoint, sim_);
    const double t = sim_.time();
    open(run, &t);
  }
  bool finished() const override { return sim_.step_count() >= steps_; }
  void advance() override { sim_.step(); }
  void check_health() override {
    if (sim_.step_count() % kHealthEvery == 0 || finished()) sim_.health_check();
  }
  void write_outputs() override { outputs_->write_due(sim_, counters_); }
  std::int64_t step() const override { return sim_.step_count(); }
  std::string position() const override { return fmt::format(" (t = {} s)", sim_.time()); }
  std::int64_t steps_left() const override { return steps_ - sim_.step_count(); }
  std::int64_t checkpoint_every() const override { return c_.output.schedule.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override { granular::write_checkpoint(file, sim_, counters_); }
  void log_results(double steps_per_second) override {
    const Thermo t = sim_.thermo();
    log_->info("finished: t = {} s after {} steps ({:.3g} grain-steps/s); energies kinetic {} J, potential {} J, "
               "total {} J (external work {} J); signal depth {} m",
               t.time, t.step, steps_per_second * static_cast<double>(sim_.size()), t.kinetic, t.potential, t.total,
               t.external_work, t.signal_depth);
  }

  // SigSpeed: the signal's mean speed since the impulse, (SigDepth − depth of grain 0) / Time (the leading peak's
  // speed between samples is signal.csv's; a thermo row cannot depend on the previous row and
  // still be the same after a resume).
  std::vector<std::string> thermo_columns() const override {
    return {"Step", "Time", "KinEng", "PotEng", "TotEng", "ExtWork", "SigDepth", "SigSpeed"};
  }
  std::vector<double> thermo_values() const override {
    const Thermo t = sim_.thermo();
    return {static_cast<double>(t.step), t.time, t.kinetic, t.potential, t.total, t.external_work, t.signal_depth,
            t.time > 0 ? (t.signal_depth - sim_.chain().depth.front()) / t.time : 0.0};
  }
  std::int64_t thermo_every() const override { return thermo_interval(c_.output.schedule.thermo_every, steps_); }
  double work_items() const override { return static_cast<double>(sim_.size()); }
  std::string work_item_name() const override { return "grain"; }
  // Grain i's displacement along the chain from its initial depth, velocity and force (+: deeper).
  std::vector<StateArray> state_arrays() override {
    const std::size_t n = sim_.size();
    return {state_array("displacements", sim_.displacement(), n, "m"),
            state_array("velocities", sim_.velocity(), n, "m/s"), state_array("forces", sim_.force(), n, "N")};
  }

  double time() const override { return sim_.time(); }
  std::string time_unit() const override { return "s"; }
  /// summary_results (outputs.hpp) with the units in the key names (docs/granular.md).
  Json results() const override {
    static constexpr const char* kUnits[] = {"_s", "", "_J", "_J", "_J", "", "_m", "_m_s", "_N"};
    const auto values = summary_results(sim_, initial_total_);
    Json out = Json::object();
    for (std::size_t j = 0; j < values.size(); ++j) {
      const std::string key = values[j].first + kUnits[j];
      if (key == "steps")
        out.set(key, static_cast<long long>(values[j].second));
      else
        out.set(key, values[j].second);
    }
    return out;
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"run.end_time", "output.*_interval", "output.thermo_every", "output.checkpoint_every"};
  }

 private:
  void open(RunContext& run, const double* resume_from) {
    log_ = &run.log;
    outputs_.emplace(run.folder, c_, sim_, steps_, resume_from);
    log_->info("running to t = {} s: {} steps of {} s ({} of the stable {} s)", c_.run.end_time, steps_,
               sim_.time_step(), sim_.time_step() / c_.run.stable_step, c_.run.stable_step);
  }

  GranularCase c_;
  Simulation sim_;
  long long steps_;
  double initial_total_;
  OutputCounters counters_;
  std::optional<RunOutputs> outputs_;
  Logger* log_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions&) {
  const GranularCase c = read_granular_case(root);
  root.check_unknown_keys();
  return std::make_unique<GranularMethod>(c);
}

}  // namespace shockfield::granular
