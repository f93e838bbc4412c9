#include "shockfield/md/run_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "shockfield/core/error.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/md/diagnostics/hugoniot.hpp"
#include "shockfield/md/fixes/msst.hpp"
#include "shockfield/md/fixes/piston.hpp"
#include "shockfield/md/ghosts.hpp"
#include "shockfield/md/minimize.hpp"
#include "shockfield/md/msst_report.hpp"
#include "shockfield/md/nphug_report.hpp"
#include "shockfield/md/state_arrays.hpp"
#include "shockfield/md/run_output.hpp"
#include "shockfield/md/run_ranks.hpp"
#include "shockfield/md/system_builder.hpp"
#include "shockfield/md/run_prepare.hpp"
#include "shockfield/md/velocity.hpp"
#include "shockfield/parallel/method_mirror.hpp"

namespace shockfield::md {

namespace fs = std::filesystem;

namespace {

// The Hugoniot state of a piston stage from its profiles (hugoniot.hpp), written and logged.
std::optional<HugoniotState> report_hugoniot(const Simulation& sim, const RunOutput& output, const OutputSpec& spec,
                     const StageSpec& stage, const fs::path& folder, Logger& log) {
  const FixPiston* piston = nullptr;
  for (const auto& fix : sim.fixes)
    if (auto* p = dynamic_cast<const FixPiston*>(fix.get())) piston = p;
  if (!piston || spec.profile_every == 0) return std::nullopt;
  std::vector<Profile> frames;
  for (Profile& p : read_profiles_csv(output.profiles_file()))
    if (p.time >= piston->start_time() - 1e-12) frames.push_back(std::move(p));
  io::CsvWriter front(folder / fmt::format("shock_front_{}.csv", stage.name),
                      {"step", "time_ps", "front_A", "piston_A"});
  for (const Profile& p : frames)
    front.row({static_cast<double>(p.step), p.time, front_position(p, piston->axis(), piston->side(), piston->speed()),
               piston->wall(p.time)});
  const HugoniotState h = extract_hugoniot(frames, piston->axis(), piston->side(), piston->speed(),
                                           piston->start_position(), piston->start_time());
  const fs::path file = folder / fmt::format("hugoniot_{}.toml", stage.name);
  write_file_atomically(file, hugoniot_toml(h));
  log.info("[{}] Hugoniot: Us = {:.3f} km/s, Up = {:.3f} km/s (piston {:.3f}), P = {:.2f} GPa "
           "(rho0 Us Up = {:.2f}), rho = {:.3f} g/cc, T = {:.0f} K -> {}{}",
           stage.name, h.us, h.up, h.piston_speed, h.pressure, h.pressure_rh, h.density, h.temperature,
           file.string(), h.note.empty() ? "" : " (" + h.note + ")");
  return h;
}


// Molecular dynamics as a plug-in of the run driver. The stages of the case run in order: a
// minimisation stage runs whole when it begins; a dynamic stage sets up its fixes and forces,
// then advance() makes its steps; a stage ends (final output, Hugoniot) lazily, at the next
// advance() or at the end of the run, so that the checkpoint position {stage, steps done} means
// what it always meant.
// Under mpirun the box is decomposed (run_ranks.hpp): every rank builds the whole system, keeps
// the atoms of its piece and steps them; rank 0 runs the driver and announces each collective
// call to the other ranks, which serve() by making the same call (parallel/method_mirror.hpp).
// The outputs are the serial ones, written by rank 0 from the gathered atoms.
class MdMethod final : public Method, public DerivedArrays {
 public:
  MdMethod(const Config& root, const RunOptions& options)
      : p_(prepare(root, options)), atoms_(p_.system.atom_count()),
        domain_(decompose_run(root, p_.md, p_.system.box, p_.potential->cutoff() + p_.md.skin, options)) {
    if (domain_) mirror_.emplace(domain_->comm());
  }
  ~MdMethod() override { announce(parallel::MethodCall::quit); }
  MdMethod(const MdMethod&) = delete;
  MdMethod& operator=(const MdMethod&) = delete;
  /// The ranks other than 0 of a decomposed run: their part of each of rank 0's calls.
  void serve() { mirror_->serve(*this); }

  std::string name() const override { return "md"; }
  std::string size_text() const override {
    if (!domain_) return fmt::format("{} atoms", atoms_);
    const parallel::Dims3& d = domain_->dims();
    return fmt::format("{} atoms, on {} ranks (rank grid {} x {} x {})", atoms_, domain_->comm().size(), d[0], d[1], d[2]);
  }
  std::string check_text() const override {
    // ~400 B an atom: position, velocity, force, ids, image and group flags, its share of the
    // ghosts and of the neighbour list (~40 neighbours within cutoff + skin in a metal).
    return fmt::format("md case ({} atoms, {} stage(s); ~{} when it runs{})", atoms_, p_.md.stages.size(),
                       memory_text(400.0 * static_cast<double>(atoms_)),
                       p_.system.counted_types.empty() ? "" : "; the crystal counted, not built");
  }

  void start(RunContext& run) override {
    announce(parallel::MethodCall::start);
    build(run);
    // Velocities of the whole system (the serial bits on every rank), then dealt out.
    if (p_.md.temperature) create_velocities(sim_->atoms, *p_.md.temperature, p_.md.seed);
    for (std::size_t k = 0; k < p_.md.velocity_adds.size(); ++k)
      add_velocity(sim_->atoms, p_.md.velocity_adds[k].velocity, p_.add_groups[k]);
    if (domain_) {
      keep_own_atoms(*domain_, sim_->atoms);
      sim_->domain = domain_;
    }
    output_.emplace(run.folder, p_.md.output, std::nullopt, writes());
    for (const auto& note : p_.notes) run.log.info("note: {}", note);
    begin_pending();
  }
  void resume(RunContext& run) override {
    if (mirror_) mirror_->announce_resume(run.checkpoint.string());
    build(run);
    const CheckpointPosition start = read_checkpoint_header(run.checkpoint);
    k_ = static_cast<std::size_t>(start.stage);
    if (k_ >= stages().size()) return;  // finished
    add_fixes();
    read_checkpoint(run.checkpoint, *sim_);  // the whole system, on every rank
    if (domain_) deal_out_checkpoint(*sim_, domain_);
    done_ = start.stage_step;
    output_.emplace(run.folder, p_.md.output, sim_->step, writes());
    begin_stage(/*fixes_added=*/true, /*mid_stage=*/done_ > 0);
    begin_pending();
  }

  bool finished() const override { return steps_left() == 0; }
  void advance() override {
    announce(parallel::MethodCall::advance);
    while (done_ >= stages()[k_].steps) finish_stage();
    sim_->advance(want_per_atom_);
    ++done_;
  }
  void check_health() override {
    announce(parallel::MethodCall::check_health);
    sim_->check_health();
  }
  void write_outputs() override {
    announce(parallel::MethodCall::write_outputs);
    output_->write(*sim_);
  }
  std::int64_t step() const override { return sim_->step; }
  std::string position() const override {
    if (k_ >= stages().size()) return " (all stages done)";
    return fmt::format(" (stage '{}', {} of {} steps done)", stages()[k_].name, done_, stages()[k_].steps);
  }
  std::int64_t steps_left() const override {
    if (k_ >= stages().size()) return 0;
    std::int64_t left = stages()[k_].steps - done_;
    for (std::size_t j = k_ + 1; j < stages().size(); ++j) left += stages()[j].steps;
    return left;
  }
  std::int64_t checkpoint_every() const override { return p_.md.output.checkpoint_every; }
  // At the end the position is the last stage with all its steps done (when it is dynamic), so
  // that a resume with more steps in it continues the run.
  void write_checkpoint(const fs::path& file) override {
    announce(parallel::MethodCall::write_checkpoint);
    const std::size_t n = stages().size();
    CheckpointPosition where{static_cast<std::int64_t>(k_), done_};
    if (k_ >= n) where = stages().back().ensemble == "minimize" ? CheckpointPosition{static_cast<std::int64_t>(n), 0}
                                                                 : CheckpointPosition{static_cast<std::int64_t>(n - 1),
                                                                                      stages().back().steps};
    if (!domain_) return md::write_checkpoint(file, *sim_, where);
    std::optional<Simulation> whole = gather_simulation(*sim_);
    if (!whole) return;
    std::swap(whole->fixes, sim_->fixes);  // their state is the same on every rank
    md::write_checkpoint(file, *whole, where);
    std::swap(whole->fixes, sim_->fixes);
  }
  void write_final_outputs() override {
    announce(parallel::MethodCall::write_final_outputs);
    while (k_ < stages().size()) finish_stage();
    io::DataWriteOptions data;
    data.shrink_margin = sim_->shrink_margin;
    if (!domain_) return io::write_data(run_->folder / "final.data", sim_->box, sim_->atoms, data);
    const Atoms atoms = gather_atoms(*domain_, sim_->atoms);
    if (writes()) io::write_data(run_->folder / "final.data", sim_->box, atoms, data);
  }
  void log_results(double) override {
    run_->log.info("finished: {} steps; final configuration in {}", sim_->step, (run_->folder / "final.data").string());
  }

  // A case with an msst stage adds the MSST columns (msst_report.hpp).
  std::vector<std::string> thermo_columns() const override {
    std::vector<std::string> c{"Step", "Time", "Temp", "PotEng", "KinEng", "TotEng", "Press"};
    if (p_.md.output.msst_axis) for (auto& name : msst_thermo_columns()) c.push_back(name);
    if (p_.md.output.nphug) for (auto& name : nphug_thermo_columns()) c.push_back(name);
    return c;
  }
  std::vector<double> thermo_values() const override {
    announce(parallel::MethodCall::thermo_values);
    const ThermoState t = sim_->thermo();
    std::vector<double> v{static_cast<double>(sim_->step), sim_->time, t.temperature, t.potential, t.kinetic,
                          t.potential + t.kinetic, t.pressure};
    if (p_.md.output.msst_axis) for (double x : msst_thermo_values(*sim_, *p_.md.output.msst_axis)) v.push_back(x);
    if (p_.md.output.nphug) for (double x : nphug_thermo_values(*sim_)) v.push_back(x);
    return v;
  }
  std::int64_t thermo_every() const override { return p_.md.output.thermo_every; }
  bool writes_thermo_csv() const override { return true; }
  double work_items() const override { return static_cast<double>(atoms_); }
  std::string work_item_name() const override { return "atom"; }
  double ns_per_step() const override { return p_.md.timestep * 1e-3; }
  std::vector<PhaseTime> phase_times() const override {
    return {{"force", sim_->force_seconds}, {"neighbour", sim_->neighbor_seconds}, {"ghosts", sim_->ghost_seconds}};
  }

  std::vector<StateArray> state_arrays() override { return atom_state_arrays(*sim_, {"Å", "Å/ps", "eV/Å", "eV"}); }
  std::vector<DerivedArray> derived_arrays() const override { return box_arrays(sim_->box, "Å"); }
  double time() const override { return sim_->time; }
  std::string time_unit() const override { return "ps"; }
  // The Hugoniot state of every piston stage ended in this session and the final energies.
  Json results() const override {
    announce(parallel::MethodCall::results);
    Json hugoniot = Json::array();
    for (const auto& [stage, h] : hugoniot_)
      hugoniot.push(Json::object()
                        .set("stage", stage)
                        .set("shock_speed_km_s", h.us)
                        .set("particle_speed_km_s", h.up)
                        .set("piston_speed_km_s", h.piston_speed)
                        .set("pressure_GPa", h.pressure)
                        .set("pressure_rankine_hugoniot_GPa", h.pressure_rh)
                        .set("density_g_cc", h.density)
                        .set("density_rankine_hugoniot_g_cc", h.density_rh)
                        .set("initial_density_g_cc", h.density0)
                        .set("temperature_K", h.temperature)
                        .set("note", h.note));
    Json msst = Json::array();
    for (const auto& r : msst_) msst.push(msst_json(r));
    Json nphug = Json::array();
    for (const auto& r : nphug_) nphug.push(nphug_json(r));
    const ThermoState t = sim_->thermo();
    return Json::object()
        .set("hugoniot", std::move(hugoniot))
        .set("msst", std::move(msst))
        .set("nphug", std::move(nphug))
        .set("final", Json::object()
                          .set("temperature_K", t.temperature)
                          .set("potential_energy_eV", t.potential)
                          .set("kinetic_energy_eV", t.kinetic)
                          .set("total_energy_eV", t.potential + t.kinetic)
                          .set("pressure_bar", t.pressure)
                          .set("volume_A3", t.volume));
  }
  // The steps of the last stage (a longer last stage continues a finished run) and the output
  // schedule.
  std::vector<std::string> resume_safe_keys() const override {
    return {fmt::format("stage[{}].steps", stages().size() - 1), "output.thermo_every", "output.checkpoint_every",
            "output.dump_every", "output.profile_every"};
  }

 private:
  const std::vector<StageSpec>& stages() const { return p_.md.stages; }
  void build(RunContext& run) {
    run_ = &run;
    sim_.emplace(p_.system.box, std::move(p_.system.atoms), std::move(p_.potential), p_.md.timestep, p_.md.skin);
    sim_->neighbor_every = p_.md.neighbor_every;
    sim_->neighbor_delay = p_.md.neighbor_delay;
    sim_->neighbor_check = p_.md.neighbor_check;
    want_per_atom_ = [this](std::int64_t step) { return output_->needs_per_atom(step); };
  }
  bool writes() const { return !domain_ || domain_->comm().is_root(); }
  void announce(parallel::MethodCall call) const {
    if (mirror_) mirror_->announce(call);
  }
  void add_fixes() { add_stage_fixes(*sim_, stages()[k_], p_.stage_groups[k_], p_.md.seed + k_); }

  // Stage k_ begins: a minimisation runs whole (and k_ moves on); a dynamic stage sets up its
  // fixes and forces unless it is resumed in its middle.
  void begin_stage(bool fixes_added, bool mid_stage) {
    const StageSpec& stage = stages()[k_];
    Simulation& sim = *sim_;
    if (!fixes_added) add_fixes();
    if (stage.ensemble == "minimize") {
      MinimizeSettings settings = stage.minimize;
      settings.group = p_.stage_groups[k_];
      const MinimizeResult r = minimize_fire(sim, settings);
      const Vec3 l = sim.box.length();
      run_->log.info("[{}] FIRE minimisation: {} after {} iterations; E = {:.10g} eV ({:.10g} eV/atom), max |f| = "
                     "{:.3g} eV/A, P = {:.3g} {:.3g} {:.3g} bar, box {:.10g} {:.10g} {:.10g} A",
                     stage.name, r.reason, r.iterations, r.energy, r.energy / static_cast<double>(sim.atoms.nlocal),
                     r.max_force, r.pressure.x(), r.pressure.y(), r.pressure.z(), l.x(), l.y(), l.z());
      sim.setup(want_per_atom_(sim.step));
      output_->write(sim, true);
      ++k_;
      return;
    }
    if (!mid_stage) {
      sim.setup(want_per_atom_(sim.step));
      for (auto& fix : sim.fixes) fix->setup(sim);
      output_->write(sim, true);
    }
    run_->log.info("[{}] {} steps, ensemble {}, dt = {} ps{}{}", stage.name, stage.steps, stage.ensemble, sim.dt,
                   stage.piston ? fmt::format(", piston {} km/s", stage.piston->speed * units::metal::A_per_ps_to_km_per_s)
                                : "",
                   stage.deform_rate || stage.deform_tilt_rate ? ", deforming" : "");
    started_ = true;
    stage_first_ = done_;
    stage_clock_ = std::chrono::steady_clock::now();
  }
  void begin_pending() {
    while (k_ < stages().size() && !started_) begin_stage(false, false);
  }
  // The started stage k_ ends (its last output and Hugoniot) and the next ones begin.
  void finish_stage() {
    const StageSpec& stage = stages()[k_];
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_clock_).count();
    run_->log.info("[{}] done at step {} ({:.1f} steps/s, {} neighbour rebuilds)", stage.name, sim_->step,
                   seconds > 0 ? static_cast<double>(done_ - stage_first_) / seconds : 0.0, sim_->rebuilds);
    output_->write(*sim_, true);
    if (auto h = report_hugoniot(*sim_, *output_, p_.md.output, stage, run_->folder, run_->log))
      hugoniot_.emplace_back(stage.name, *h);
    if (const FixMsst* msst = find_msst(*sim_)) {
      msst_.push_back(make_msst_report(*sim_, *msst, stage.name));
      run_->log.info("{}", msst_log_line(msst_.back()));
      write_hugoniot_state(stage.name, msst_hugoniot_state(msst_.back()));
    }
    if (const FixNphug* nphug = find_nphug(*sim_)) {
      nphug_.push_back(make_nphug_report(*sim_, *nphug, stage.name));
      run_->log.info("{}", nphug_log_line(nphug_.back()));
      write_hugoniot_state(stage.name, nphug_hugoniot_state(nphug_.back()));
    }
    started_ = false;
    ++k_;
    done_ = 0;
    begin_pending();
  }

  // hugoniot_<stage>.toml of an msst or nphug stage (a piston stage's is report_hugoniot's).
  void write_hugoniot_state(const std::string& stage, const HugoniotState& h) const {
    write_file_atomically(run_->folder / fmt::format("hugoniot_{}.toml", stage), hugoniot_toml(h));
  }

  Prepared p_;  ///< its system and potential move into sim_ when the run starts
  std::size_t atoms_;
  std::optional<Simulation> sim_;
  std::optional<RunOutput> output_;
  std::shared_ptr<Decomposition> domain_;  ///< the rank grid under mpirun; null on one rank
  std::optional<parallel::MethodMirror> mirror_;
  std::function<bool(std::int64_t)> want_per_atom_;
  std::vector<std::pair<std::string, HugoniotState>> hugoniot_;  ///< stages ended in this session
  std::vector<MsstReport> msst_;                                 ///< msst stages ended in this session
  std::vector<NphugReport> nphug_;                               ///< nphug stages ended in this session
  RunContext* run_ = nullptr;
  std::size_t k_ = 0;           ///< current stage
  std::int64_t done_ = 0;       ///< steps done in it
  bool started_ = false;        ///< stage k_ has begun
  std::int64_t stage_first_ = 0;
  std::chrono::steady_clock::time_point stage_clock_;
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options) {
  return std::make_unique<MdMethod>(root, options);
}

void serve_ranks(const Config& root, const RunOptions& options) {
  MdMethod method(root, options);  // bad input: thrown on every rank
  method.serve();
}

void run_case(const Config& root, const RunOptions& options) { run_method(root, options, &make_method); }

}  // namespace shockfield::md
