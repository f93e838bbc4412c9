#include "shockfield/dbm/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <memory>
#include <optional>

#include "shockfield/core/derived_arrays.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/state_array.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/checkpoint.hpp"
#include "shockfield/dbm/decomposition.hpp"
#include "shockfield/dbm/detonation.hpp"
#include "shockfield/dbm/gls_run.hpp"
#include "shockfield/dbm/reaction.hpp"
#include "shockfield/dbm/reaction_case.hpp"
#include "shockfield/dbm/run_output.hpp"
#include "shockfield/dbm/stability_case.hpp"
#include "shockfield/dbm/tne.hpp"

namespace shockfield::dbm {

namespace fs = std::filesystem;

namespace {

void derive(const Config& root, const DbmCase& c, const Simulation& sim) {
  root.derive("cells", static_cast<long long>(c.lattice.nx) * c.lattice.ny);
  root.derive("degrees_of_freedom_b", sim.b());
  root.derive("max_speed", c.model.max_speed());
  root.derive("moment_condition_number", sim.inversion().condition_number());
  root.derive("time_step", c.bgk.dt);
  root.derive("steps", c.steps);
  root.derive("courant", c.model.max_speed() * c.bgk.dt / c.lattice.dx);
  root.derive("dt_over_tau", c.bgk.dt / c.bgk.tau);
  if (c.exact_star) {
    root.derive("exact_p_star", c.exact_star->p);
    root.derive("exact_u_star", c.exact_star->u);
    root.derive("exact_rho_star_left", c.exact_star->rho_left);
    root.derive("exact_rho_star_right", c.exact_star->rho_right);
  }
  if (c.reaction) derive_reaction(root, *c.reaction);
  if (c.gls) {  // GLS: the time-step limit and the densities it was checked for
    const GlsCaseSpec& g = *c.gls;
    const GlsStepLimit limit = gls_step_limit(g.settings, c.lattice, c.model.max_speed(), c.bgk.tau, g.quench.T,
                                              g.rho_vapour, g.rho_liquid);
    root.derive("gls_stable_time_step", limit.dt);
    root.derive("gls_time_step_limited_by", limit.cause);
    root.derive("gls_expected_rho_vapour", g.rho_vapour);
    root.derive("gls_expected_rho_liquid", g.rho_liquid);
    root.derive("gls_heat_conductivity_per_rho_T", 2.0 * (c.bgk.tau - g.settings.q));
  }
}

// The discrete Boltzmann method as a plug-in of the run driver: a whole number of steps of dt to
// end_time; rows and frames at the first step at or past k·interval.
// Under mpirun (or with --rank-grid) the lattice is decomposed (decomposition.hpp): the ranks
// step their blocks; sim_ is rank 0's whole lattice, refreshed from the blocks (current()) before
// anything reads its state, and the other ranks only serve().
class DbmMethod final : public Method, public DerivedArrays {
 public:
  DbmMethod(const Config& root, const DbmCase& c, const CaseStability& stability, const RunOptions& options)
      : c_(c), sim_(c_.model, c_.lattice, c_.boundaries, c_.bgk, false), tol_(kOutputTimeTolerance * c_.bgk.dt) {
    // The lattice's arrays (distributions, reactant, GLS force) are allocated when the run starts
    // (allocate()), so that --check validates a lattice of any allowed size without them.
    if (c_.gls) GlsForce::validate(sim_, c_.boundaries, c_.gls->settings);
    derive(root, c_, sim_);
    derive_stability(root, stability);
    if (parallel::Communicator::world().size() > 1 || !options.rank_grid.empty())
      decomposition_ = std::make_unique<Decomposition>(c_, options.rank_grid);
  }
  /// The ranks other than 0: the blocks' part of the run, driven by rank 0.
  void serve() { decomposition_->serve(); }

  std::string name() const override { return "dbm"; }
  std::string size_text() const override {
    const std::string ranks =
        decomposition_ ? fmt::format(", on {} ranks (rank grid {} x {} x {})", decomposition_->grid().comm().size(),
                                     decomposition_->grid().dims()[0], decomposition_->grid().dims()[1],
                                     decomposition_->grid().dims()[2])
                       : "";
    return fmt::format("{} x {} cells, D2V16{}, tau {}{}", c_.lattice.nx, c_.lattice.ny,
                       c_.gls ? ", GLS liquid-vapour" : "", c_.bgk.tau, ranks);
  }
  std::string check_text() const override {
    // The distributions, and per cell 5 reactant arrays with [reaction] and 56 GLS values (GlsForce:
    // 4 coefficients, and its Scratch of 4 macroscopic values, 28 fields and 20 half spectra).
    const double cells = static_cast<double>(c_.lattice.nx) * c_.lattice.ny;
    const double bytes = Simulation::bytes(c_.lattice, c_.model, c_.bgk.spectral_convection) +
                         8.0 * cells * (c_.reaction ? 5.0 : 0.0) + 8.0 * cells * (c_.gls ? 56.0 : 0.0);
    return fmt::format("dbm case ({} x {} cells, {} steps, dt {:.3g}; {} cells, {} when it runs)", c_.lattice.nx,
                       c_.lattice.ny, c_.steps, c_.bgk.dt, c_.lattice.nx * static_cast<long long>(c_.lattice.ny),
                       memory_text(bytes));
  }

  void start(RunContext& run) override {
    allocate();
    if (gls_) {
      gls_->initialize(sim_);
    } else {
      const InitialSpec& init = c_.initial;
      const auto initial = [&](double x, double) { return x < init.split ? init.left : init.right; };
      if (reaction_)
        initialize_detonation(sim_, *reaction_, c_.reaction->ignition, c_.reaction->theory, initial);
      else
        sim_.initialize(initial);
    }
    if (decomposition_) decomposition_->scatter(sim_);
    open(run, false);
    write_due();
  }
  void resume(RunContext& run) override {
    allocate();
    counters_ = read_checkpoint(run.checkpoint, sim_, reactant());
    if (decomposition_) decomposition_->scatter(sim_);
    open(run, true);
    // A finished GLS run resumed has nothing to step: its summary.csv is written again from series.csv,
    // so a run folder of an older build gains the summary columns added since (u_DG).
    if (gls_ && finished()) phase_summary_ = write_phase_summary(run.folder, *c_.gls, run.log);
  }
  bool finished() const override { return sim_.steps() >= c_.steps; }
  void advance() override {
    if (!decomposition_) return sim_.step();
    healthy_ = decomposition_->step();
    sim_.restore_clock(decomposition_->block().time(), decomposition_->block().steps());
  }
  void check_health() override {
    if (decomposition_ && healthy_) return;
    current().check_state();  // the whole lattice names the cell, as a one-rank run does
    if (!healthy_) throw RunError("DBM state broke down on a rank, but not in the gathered lattice");
  }
  void write_outputs() override { write_due(); }
  std::int64_t step() const override { return sim_.steps(); }
  std::string position() const override { return fmt::format(" (t = {})", sim_.time()); }
  double fraction_done() const override { return sim_.time() / c_.end_time; }
  std::int64_t steps_left() const override { return c_.steps - sim_.steps(); }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override { dbm::write_checkpoint(file, current(), counters_, reactant()); }
  std::string write_stop_state() override {
    output_->write_profile(current(), counters_.profiles);
    return fmt::format("the state in profiles/profile_{}.csv", counters_.profiles);
  }
  std::string write_failure_state() override {
    output_->write_profile(current(), counters_.profiles);
    if (gls_) {
      run_->log.info("{}", GlsRunPart::blow_up_hint());
      phase_summary_ = write_phase_summary(run_->folder, *c_.gls, run_->log);
    }
    return fmt::format("the state at the failure: profiles/profile_{}.csv", counters_.profiles);
  }
  void write_final_outputs() override {
    if (c_.output.profile_interval == 0.0) output_->write_profile(current(), counters_.profiles++);
  }
  void log_results(double steps_per_second) override {
    if (gls_) phase_summary_ = write_phase_summary(run_->folder, *c_.gls, run_->log);
    const auto total = current().totals();
    const char* per = units::model::per_missing_dimensions_text(Lattice::dim);
    run_->log.info("finished: t = {} after {} steps ({:.3g} cell-steps/s); mass {}, momentum ({}, {}), energy {} "
                   "(model units,{})",
                   sim_.time(), sim_.steps(), steps_per_second * work_items(), total[0], total[1], total[2],
                   total[3], per);
    if (reaction_)
      run_->log.info("chemical energy Q*sum(rho*lambda) {}; energy + chemical energy {} (model units,{})",
                     reaction_->chemical_energy(), total[3] + reaction_->chemical_energy(), per);
  }

  std::vector<std::string> thermo_columns() const override {
    std::vector<std::string> columns{"Step", "Time", "Mass", "Px", "TotEng", "MeanD"};
    if (c_.reaction) columns.insert(columns.end(), {"ChemEng", "FrontX"});
    return columns;
  }
  std::vector<double> thermo_values() const override {
    const auto total = current().totals();
    std::vector<double> values{static_cast<double>(sim_.steps()), sim_.time(), total[0], total[1], total[3],
                               tne_measures(sim_).mean_strength};
    if (reaction_)
      values.insert(values.end(), {reaction_->chemical_energy(),
                                   pressure_front(sim_, c_.output.profile_row, c_.reaction->front_pressure())});
    return values;
  }
  std::int64_t thermo_every() const override { return thermo_interval(c_.output.thermo_every, c_.steps); }
  double work_items() const override { return static_cast<double>(c_.lattice.nx) * c_.lattice.ny; }
  std::string work_item_name() const override { return "cell"; }
  // f_k on every cell, ghosts included: (Q, ny + 4, nx + 4), interior [:, 2:-2, 2:-2] (lattice.hpp).
  // A decomposed run steps its blocks, not sim_ (rank 0's gathered copy): no views there.
  std::vector<StateArray> state_arrays() override {
    if (decomposition_) return {};
    sim_.keep_f_in_place();
    const Lattice& l = c_.lattice;
    const int ghosts = 2 * Lattice::ghosts;
    return {grid_state_array("f", sim_.f(), 3, {l.nx + ghosts, l.ny + ghosts, sim_.model().size()})};
  }

  // ρ, u (vx, vy) and T of every interior cell, the moments of f (docs/theory/dbm.md) as the field
  // frames hold them (Simulation::macro, macro_cell_image): (ny, nx), x fastest.
  std::vector<DerivedArray> derived_arrays() const override {
    if (decomposition_) return {};
    const Lattice& l = c_.lattice;
    const auto nx = static_cast<std::size_t>(l.nx), ny = static_cast<std::size_t>(l.ny);
    DerivedArray rho{"rho", std::vector<double>(nx * ny), {ny, nx}, "1"};
    DerivedArray u{"velocity", std::vector<double>(2 * nx * ny), {ny, nx, 2}, "1"};
    DerivedArray T{"T", std::vector<double>(nx * ny), {ny, nx}, "1"};
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const Macro m = sim_.macro(static_cast<int>(i), static_cast<int>(j));
        const std::size_t c = i + nx * j;
        rho.values[c] = m.rho, u.values[2 * c] = m.ux, u.values[2 * c + 1] = m.uy, T.values[c] = m.T;
      }
    return {std::move(rho), std::move(u), std::move(T)};
  }

  double time() const override { return sim_.time(); }
  std::string time_unit() const override { return "1"; }
  // Domain totals, the mean TNE strength and the means of the central TNE measures (eq. 35 and
  // its components), for [reaction] the chemical energy and the tracked front, and for GLS the
  // phase-separation summary once written (t_SD, R_SD, D_max, u_DG, ...: a sweep's CSV carries them).
  Json results() const override {
    const auto total = current().totals();
    const TneFields tne = tne_measures(sim_);
    Json means = Json::object();
    for (std::size_t k = 0; k < tne.mean_central.size(); ++k) means.set(kTneNames[k], tne.mean_central[k]);
    Json r = Json::object();
    const std::string per = units::model::per_missing_dimensions_column(Lattice::dim);
    r.set("mass" + per, total[0]).set("momentum" + per, Json::Array{total[1], total[2]}).set("energy" + per, total[3]);
    r.set("mean_tne_strength_D", tne.mean_strength).set("mean_tne_central", std::move(means));
    if (phase_summary_) r.set("phase_separation", phase_summary_json(*phase_summary_));
    if (reaction_) {
      r.set("chemical_energy" + per, reaction_->chemical_energy());
      r.set("front_x", pressure_front(sim_, c_.output.profile_row, c_.reaction->front_pressure()));
    }
    return r;
  }
  // end_time is not safe: dt is set so that a whole number of steps lands on it.
  std::vector<std::string> resume_safe_keys() const override {
    return {"output.*_interval", "output.thermo_every", "output.checkpoint_every", "output.growth_window"};
  }

 private:
  // The lattice's arrays; [reaction]: the reactive DBM installs its source on sim (reaction.hpp).
  void allocate() {
    sim_.allocate();
    if (c_.reaction)
      reaction_ = std::make_unique<ReactiveFlow>(sim_, c_.boundaries, c_.reaction->law, c_.reaction->inflow_lambda);
    if (c_.gls) gls_.emplace(sim_, c_);
  }
  std::vector<double>* reactant() { return reaction_ ? &reaction_->reactant_density() : nullptr; }
  void open(RunContext& run, bool resumed) {
    run_ = &run;
    output_.emplace(run.folder, c_.output, resumed ? &sim_ : nullptr, counters_, reaction_.get(), c_.reaction,
                    gls_ ? &*gls_ : nullptr);
    if (!finished())
      run.log.info("running to t = {} in {} steps of dt = {} (tau = {}, Courant {:.3g})", c_.end_time, c_.steps,
                   c_.bgk.dt, c_.bgk.tau, c_.model.max_speed() * c_.bgk.dt / c_.lattice.dx);
  }
  void write_due() {
    const double t = sim_.time() + tol_;
    write_due_frames(counters_.series, c_.output.series_interval, t, [&](auto) { output_->write_series(current()); });
    write_due_frames(counters_.profiles, c_.output.profile_interval, t,
                     [&](auto k) { output_->write_profile(current(), k); });
    write_due_frames(counters_.fields, c_.output.field_interval, t, [&](auto) { output_->write_fields(current()); });
  }
  // The whole lattice's state: with a decomposition, gathered from the blocks once per step
  // that needs it (a const method may gather: sim_ is what the blocks hold, brought over).
  const Simulation& current() const {
    if (decomposition_ && gathered_step_ != sim_.steps()) {
      decomposition_->gather(const_cast<Simulation&>(sim_));
      gathered_step_ = sim_.steps();
    }
    return sim_;
  }

  DbmCase c_;
  Simulation sim_;
  double tol_;
  std::unique_ptr<ReactiveFlow> reaction_;
  std::optional<GlsRunPart> gls_;
  std::optional<PhaseSummary> phase_summary_;  // GLS: summary.csv's values, once written (results())
  OutputCounters counters_;
  std::optional<RunOutput> output_;
  RunContext* run_ = nullptr;
  std::unique_ptr<Decomposition> decomposition_;
  bool healthy_ = true;                      // the blocks' last check_state
  mutable long long gathered_step_ = -1;     // the step sim_ was last gathered at
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options) {
  DbmCase c = read_dbm_case(root);
  // The linear check is for the BGK model; the GLS force is outside it (docs/theory/dbm.md).
  const CaseStability stability = c.gls ? CaseStability{} : check_case_stability(root.table("model"), c);
  root.check_unknown_keys();
  return std::make_unique<DbmMethod>(root, c, stability, options);
}

void serve_ranks(const Config& root, const RunOptions& options) {
  const std::unique_ptr<Method> method = make_method(root, options);  // bad input: thrown on every rank
  try {
    static_cast<DbmMethod&>(*method).serve();
  } catch (const std::exception&) {
    // A failure of this rank alone (out of memory): rank 0 waits in a collective, so end them all.
    parallel::Communicator::world().abort(3);
  }
}

void run_case(const Config& root, const RunOptions& options) { run_method(root, options, &make_method); }

}  // namespace shockfield::dbm
