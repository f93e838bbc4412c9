#include "shockfield/macroparticle/run_case.hpp"

#include <fmt/format.h>

#include <optional>

#include "shockfield/core/output_schedule.hpp"
#include "shockfield/macroparticle/case_file.hpp"
#include "shockfield/macroparticle/outputs.hpp"
#include "shockfield/macroparticle/rod.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/md/state_arrays.hpp"

namespace shockfield::macroparticle {

namespace fs = std::filesystem;

namespace {

// The rod runs in the MD engine's reduced units (reduced_units.hpp): its checkpoint says so.
const md::CheckpointUnits kCheckpointUnits{"macroparticle", "reduced (macroparticle/reduced_units.hpp)", "1", "1", "1",
                                           "1", false};

class MacroparticleMethod final : public Method {
  // md's health check (non-finite values, a particle faster than the neighbour skin allows) runs
  // every kHealthEvery steps and on the last one.
  static constexpr long long kHealthEvery = 64;

 public:
  explicit MacroparticleMethod(const MacroparticleCase& c) : c_(c), rod_(c_) {}

  std::string name() const override { return "macroparticle"; }
  std::string size_text() const override { return fmt::format("{} particles", rod_.size()); }
  std::string check_text() const override {
    return fmt::format("macroparticle case ({} particles of r0 = {:.4g} m, {} steps of {:.3g} s)", rod_.size(),
                       c_.law.r0, c_.steps, c_.dt);
  }

  void start(RunContext& run) override {
    open(run, std::nullopt);
    write_outputs();
  }
  void resume(RunContext& run) override {
    md::read_checkpoint(run.checkpoint, rod_.sim(), kCheckpointUnits.method);
    open(run, rod_.sim().step);
  }
  bool finished() const override { return rod_.sim().step >= c_.steps; }
  void advance() override { rod_.advance(outputs_->needs_per_atom(rod_.sim().step + 1)); }
  void check_health() override {
    if (rod_.sim().step % kHealthEvery == 0 || finished()) rod_.sim().check_health();
  }
  void write_outputs() override { outputs_->write_due(rod_); }
  std::int64_t step() const override { return rod_.sim().step; }
  std::string position() const override { return fmt::format(" (t = {} s)", rod_.sim().time * rod_.units().time()); }
  std::int64_t steps_left() const override { return c_.steps - rod_.sim().step; }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override {
    md::write_checkpoint(file, rod_.sim(), {0, rod_.sim().step}, kCheckpointUnits);
  }
  void log_results(double steps_per_second) override {
    const RodMeasures m = rod_.measure();
    log_->info("finished: t = {} s after {} steps ({:.3g} particle-steps/s); strain {:.6g}, stress {:.6g} Pa, "
               "lateral strain {:.6g}; secant E {:.6g} Pa (eq 15: {:.6g} Pa, [001] lattice: {:.6g} Pa), ν {:.4g}",
               m.time, rod_.sim().step, steps_per_second * static_cast<double>(rod_.size()), m.strain, m.stress,
               m.lateral_strain, m.youngs(), c_.law.youngs_eq15(), c_.law.youngs_lattice_001(), m.poisson());
  }

  std::vector<std::string> thermo_columns() const override {
    return {"Step", "Time", "Temp", "KinEng", "PotEng", "Strain", "Stress", "LatStrain", "Young", "Poisson"};
  }
  std::vector<double> thermo_values() const override {
    const RodMeasures m = rod_.measure();
    return {static_cast<double>(rod_.sim().step), m.time, m.temperature, m.kinetic, m.potential, m.strain,
            m.stress, m.lateral_strain, m.youngs(), m.poisson()};
  }
  std::int64_t thermo_every() const override { return thermo_interval(c_.output.thermo_every, c_.steps); }
  double work_items() const override { return static_cast<double>(rod_.size()); }
  std::string work_item_name() const override { return "particle"; }
  // The engine's arrays in its reduced units: the unit text is one engine unit in SI.
  std::vector<StateArray> state_arrays() override {
    const ReducedUnits& u = rod_.units();
    return md::atom_state_arrays(rod_.sim(),
                                 {fmt::format("{:.9g} m", u.length), fmt::format("{:.9g} m/s", u.velocity()),
                                  fmt::format("{:.9g} N", u.force()), fmt::format("{:.9g} J", u.energy)});
  }
  std::vector<PhaseTime> phase_times() const override {
    const md::Simulation& s = rod_.sim();
    return {{"force", s.force_seconds}, {"neighbor", s.neighbor_seconds}, {"ghost", s.ghost_seconds}};
  }

  double time() const override { return rod_.sim().time * rod_.units().time(); }
  std::string time_unit() const override { return "s"; }
  Json results() const override {
    const RodMeasures m = rod_.measure();
    Json out = Json::object();
    out.set("particles", static_cast<long long>(rod_.size()));
    out.set("strain", m.strain);
    out.set("stress_Pa", m.stress);
    out.set("lateral_strain", m.lateral_strain);
    out.set("youngs_secant_Pa", m.youngs());
    out.set("poisson_secant", m.poisson());
    out.set("youngs_eq15_Pa", c_.law.youngs_eq15());
    out.set("youngs_lattice_001_Pa", c_.law.youngs_lattice_001());
    out.set("kinetic_J", m.kinetic);
    out.set("potential_J", m.potential);
    out.set("temperature_K", m.temperature);
    if (const BondTable* bonds = rod_.bonds()) {
      out.set("plastic_bonds", static_cast<long long>(bonds->size()));
      out.set("broken_bonds", static_cast<long long>(bonds->broken()));
    }
    return out;
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"loading.final_strain", "run.steps", "output.thermo_every", "output.dump_every", "output.vtk_every",
            "output.checkpoint_every"};
  }

 private:
  void open(RunContext& run, std::optional<std::int64_t> resume_step) {
    log_ = &run.log;
    outputs_.emplace(run.folder, c_.output, resume_step);
    for (const std::string& note : c_.material_notes) log_->info("material file: {}", note);
    log_->info("running {} steps of {} s ({:.3g} of the stable {:.4g} s); r0 = {:.6g} m, {:.6g} atoms per particle, "
               "E: eq 15 {:.6g} Pa, [001] lattice {:.6g} Pa, ν [001] lattice {:.4g}",
               c_.steps, c_.dt, c_.dt / c_.law.stable_time_step(), c_.law.stable_time_step(), c_.law.r0,
               c_.law.atoms_per_particle, c_.law.youngs_eq15(), c_.law.youngs_lattice_001(),
               c_.law.poisson_lattice_001());
  }

  MacroparticleCase c_;
  Rod rod_;
  std::optional<RodOutputs> outputs_;
  Logger* log_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions&) {
  const MacroparticleCase c = read_macroparticle_case(root);
  root.check_unknown_keys();
  auto method = std::make_unique<MacroparticleMethod>(c);
  root.derive("particles", std::stoll(method->size_text()));
  return method;
}

}  // namespace shockfield::macroparticle
