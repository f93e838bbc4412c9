#include "shockfield/mpm/run_case.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>

#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/state_array.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/mpm/case_builder.hpp"
#include "shockfield/mpm/case_file.hpp"
#include "shockfield/mpm/checkpoint.hpp"
#include "shockfield/mpm/diagnostics.hpp"
#include "shockfield/mpm/run_output.hpp"
#include "shockfield/mpm/shock_front.hpp"

namespace shockfield::mpm {

namespace fs = std::filesystem;

namespace {

// Resolved values the run echoes under [derived] (Xu et al. (2015) §2.2.2 step; shock state of the linear
// Us-Up Hugoniot for the loading speed).
void derive(const Config& root, const MpmCase& c, const BuiltSample& sample, const Simulation& sim, double first_dt) {
  root.derive("particles", static_cast<long long>(sim.particles().size()));
  root.derive("grid_nodes", static_cast<long long>(sim.grid().size()));
  root.derive("time_step_initial_s", first_dt);
  root.derive("estimated_steps", static_cast<long long>(std::ceil(c.end_time / first_dt)));
  if (c.options.contact.enabled) root.derive("contact_bodies", static_cast<long long>(sim.contact_bodies()));
  for (std::size_t k = 0; k < sample.stats.size(); ++k)
    if (c.bodies[k].pores || c.bodies[k].cavity)
      root.derive(fmt::format("body{}_porosity", k), sample.stats[k].porosity());
  for (const auto& m : c.materials) {
    root.derive(m.name + "_longitudinal_speed_m_s", m.longitudinal_speed(m.eos.rho0, 0.0));
    root.derive(m.name + "_bulk_sound_speed_m_s", m.eos.c0);
    // Hugoniot elastic limit of the J2 solid in uniaxial strain (1D, plane strain or 3D along the shock).
    if (const double hel = hugoniot_elastic_limit(m); hel > 0) root.derive(m.name + "_hel_Pa", hel);
  }
  if (c.loading == LoadingKind::Wall || c.loading == LoadingKind::Symmetric) {
    const auto& eos = c.materials[static_cast<std::size_t>(c.bodies[0].body.material)].eos;
    const double up = c.speed, us = eos.shock_speed(up);
    root.derive("hugoniot_shock_speed_m_s", us);
    root.derive("hugoniot_pressure_Pa", eos.rho0 * us * up);
    root.derive("hugoniot_density_kg_m3", eos.rho0 * us / (us - up));
  }
}

// The sample, built once the whole case file was read (every key known).
BuiltSample build_checked_sample(const MpmCase& c, const Config& root) {
  BuiltSample sample = build_sample(c, root);
  root.check_unknown_keys();
  return sample;
}

// The material point method as a plug-in of the run driver: adaptive (or fixed, CFL-checked)
// steps shortened to land on every output time and on end_time.
class MpmMethod final : public Method {
 public:
  MpmMethod(const Config& root, const RunOptions&)
      : c_(read_mpm_case(root)), sample_(build_checked_sample(c_, root)),
        sim_(c_.grid, c_.materials, std::move(sample_.particles), c_.options),
        first_dt_(c_.time_step.value_or(sim_.stable_time_step())), tol_(1e-9 * c_.end_time) {
    if (c_.time_step && *c_.time_step > sim_.stable_time_step())
      root.table("solver").fail("time_step", fmt::format("{} s is beyond the CFL limit {} s = dx / max(c + |v|) (or "
                                                         "dx²/(2dα) with heat_conduction) of the initial state",
                                                         *c_.time_step, sim_.stable_time_step()));
    derive(root, c_, sample_, sim_, first_dt_);
  }

  std::string name() const override { return "mpm"; }
  std::string size_text() const override {
    return fmt::format("{} particles, {} grid nodes, {}D", sim_.particles().size(), sim_.grid().size(), c_.grid.dim);
  }
  std::string check_text() const override {
    // ~500 B a particle (size_limits.hpp), 104 B a node (mass, momentum, force, velocity, acceleration).
    const double bytes = 500.0 * static_cast<double>(sim_.particles().size()) +
                         104.0 * static_cast<double>(sim_.grid().size());
    return fmt::format("mpm case ({} particles, {} grid nodes, dt {:.3g} s; ~{} when it runs)", sim_.particles().size(),
                       sim_.grid().size(), first_dt_, memory_text(bytes));
  }

  void start(RunContext& run) override {
    open(run, std::nullopt, make_tracker());
    write_due();
    log_plan();
  }
  void resume(RunContext& run) override {
    std::optional<CavityTracker> tracker = make_tracker();
    std::vector<double> cavity_state;
    counters_ = read_checkpoint(run.checkpoint, sim_, cavity_state);
    if (tracker && !cavity_state.empty()) tracker->restore(cavity_state);
    open(run, ResumePoint{sim_.step_count(), sim_.time()}, std::move(tracker));
    if (!finished()) log_plan();
  }

  bool finished() const override { return !(sim_.time() < c_.end_time - tol_); }

  // One step; a fixed time step is checked against the CFL limit Δx/max(c_p + |v_p|) (and the
  // diffusion limit with heat conduction) first.
  void advance() override {
    double max_dt = next_event() - sim_.time();
    if (c_.time_step) {
      const double limit = sim_.stable_time_step();  // courant = 1 for fixed steps
      if (*c_.time_step > limit)
        throw RunError(fmt::format("mpm: time_step {} s is beyond the CFL limit {} s = dx / max(c + |v|) (or "
                                   "dx²/(2dα) with heat_conduction) at t = {} s (step {}); lower [solver] time_step "
                                   "or drop it for the adaptive step",
                                   *c_.time_step, limit, sim_.time(), sim_.step_count()));
      max_dt = std::min(max_dt, *c_.time_step);
    }
    sim_.step(max_dt);
  }

  // NaN, negative density: the step that went wrong is named, the outputs are kept.
  void check_health() override {
    const Particles& p = std::as_const(sim_).particles();  // the non-const accessor drops the cached fastest speed
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double rho = p.density(i);
      if (!p.x[i].allFinite() || !p.v[i].allFinite() || !std::isfinite(p.state[i].pressure))
        throw RunError(fmt::format("mpm: particle {} has a non-finite position, velocity or pressure at t = {} s "
                                   "(step {})", i, sim_.time(), sim_.step_count()));
      if (!(rho > 0.0))
        throw RunError(fmt::format("mpm: particle {} has density {} kg/m^3 at t = {} s (step {})", i, rho,
                                   sim_.time(), sim_.step_count()));
    }
  }

  void write_outputs() override { write_due(); }
  // With [shock_front]: the Hugoniot state from every frame of shock_front.csv, written and logged.
  void write_final_outputs() override {
    hugoniot_ = output_->write_hugoniot();
    if (!hugoniot_) return;
    const ShockHugoniot& h = *hugoniot_;
    const std::size_t sq = static_cast<std::size_t>(c_.grid.dim) + 3;  // σ_aa in window_quantities
    const auto stress = [&](const WaveState& w) { return w.plateau.empty() ? NAN : w.plateau[sq].mean; };
    if (h.precursor)
      log_->info("shock front: elastic precursor at {:.6g} m/s, u_p = {:.6g} m/s, sigma_aa = {:.6g} Pa ({} frames)",
                 h.precursor->us, h.precursor->up, stress(*h.precursor), h.precursor->frames);
    log_->info("shock front: Us = {:.6g} +- {:.3g} m/s, u_p = {:.6g} m/s, sigma_aa = {:.6g} Pa (Rankine-Hugoniot "
               "{:.6g}), rho = {:.6g} kg/m^3 (Rankine-Hugoniot {:.6g}) over {} frames -> {}{}",
               h.shock.us, h.shock.us_stderr, h.shock.up, stress(h.shock), h.shock.stress_rh,
               h.shock.plateau.empty() ? NAN : h.shock.plateau[0].mean, h.shock.density_rh, h.shock.frames,
               output_->hugoniot_file()->filename().string(), h.note.empty() ? "" : " (" + h.note + ")");
  }
  std::int64_t step() const override { return sim_.step_count(); }
  std::string position() const override { return fmt::format(" (t = {} s)", sim_.time()); }
  double fraction_done() const override { return (sim_.time() - start_time_) / (c_.end_time - start_time_); }
  std::int64_t steps_left() const override {
    return static_cast<std::int64_t>(std::ceil((c_.end_time - sim_.time()) / first_dt_));
  }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override {
    mpm::write_checkpoint(file, sim_, counters_, output_->cavity() ? output_->cavity()->state() : std::vector<double>{});
  }

  std::string write_failure_state() override {
    io::VtkArray density{"density", 1, {}};
    std::vector<double> xyz;
    for (const Vec3& x : sim_.particles().x) xyz.insert(xyz.end(), {x[0], x[1], x[2]});
    for (std::size_t i = 0; i < sim_.particles().size(); ++i) density.values.push_back(sim_.particles().density(i));
    io::write_vtp(folder_ / "failure.vtp", xyz, {density}, io::VtkEncoding::Ascii);
    return "particles at the failure: failure.vtp";
  }

  void log_results(double steps_per_second) override {
    const Totals t = totals(sim_.particles());
    const char* per = units::si::per_missing_dimensions_text(sim_.grid().dim());
    log_->info("finished: t = {} s after {} steps ({:.3g} particle-steps/s); energy {} J{}, momentum ({}, {}, {}) kg m/s{}",
               sim_.time(), sim_.step_count(), steps_per_second * static_cast<double>(sim_.particles().size()),
               t.total(), per, t.momentum[0], t.momentum[1], t.momentum[2], per);
  }

  std::vector<std::string> thermo_columns() const override {
    return {"Step", "Time", "Dt", "KinEng", "IntEng", "TotEng", "MaxPress", "MaxTemp"};
  }
  std::vector<double> thermo_values() const override {
    const Particles& p = sim_.particles();
    const Totals t = totals(p);
    double pmax = -INFINITY, tmax = -INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i)
      pmax = std::max(pmax, p.state[i].pressure), tmax = std::max(tmax, p.state[i].temperature);
    return {static_cast<double>(sim_.step_count()), sim_.time(), sim_.last_time_step(), t.kinetic, t.internal,
            t.total(), pmax, tmax};
  }
  std::int64_t thermo_every() const override {
    return thermo_interval(c_.output.thermo_every, static_cast<long long>(std::ceil(c_.end_time / first_dt_)));
  }
  double work_items() const override { return static_cast<double>(sim_.particles().size()); }
  std::string work_item_name() const override { return "particle"; }

  std::vector<StateArray> state_arrays() override {
    Particles& p = sim_.particles();  // also tells the simulation its particles may be written
    using State = materials::PointState;
    // Each particle's material state (materials/solid_material.hpp) as strided views, one value per particle.
    return {state_array("positions", p.x, p.size(), "m"), state_array("velocities", p.v, p.size(), "m/s"),
            state_array("masses", p.mass, p.size(), "kg"), state_array("volumes0", p.volume0, p.size(), "m³"),
            state_array("materials", p.material, p.size()),
            member_state_array("pressures", p.state, [](State& s) -> double& { return s.pressure; }, "Pa"),
            member_state_array("viscous_pressures", p.state, [](State& s) -> double& { return s.viscous_pressure; }, "Pa"),
            member_state_array("energies", p.state, [](State& s) -> double& { return s.energy; }, "J/kg"),
            member_state_array("temperatures", p.state, [](State& s) -> double& { return s.temperature; }, "K"),
            member_state_array("plastic_works", p.state, [](State& s) -> double& { return s.plastic_work; }, "J/kg"),
            member_state_array("plastic_strains", p.state,
                               [](State& s) -> double& { return s.deviatoric.plastic_strain; }),
            member_state_array("damages", p.state, [](State& s) -> double& { return s.damage; }),
            member_state_array("deviators", p.state, [](State& s) -> Mat3& { return s.deviatoric.s; }, "Pa"),
            member_state_array("deformations", p.state, [](State& s) -> Mat3& { return s.deformation; })};
  }
  double time() const override { return sim_.time(); }
  std::string time_unit() const override { return "s"; }
  // Energies and momentum, and the means over all particles and over each bottom window of
  // [diagnostics] (the series.csv columns) at the current time.
  Json results() const override {
    const Particles& p = sim_.particles();
    const Totals t = totals(p);
    const std::vector<WindowQuantity> quantities = window_quantities(c_.grid.dim);
    const auto means = [&](const WindowStats& w) {  // keys with units, as the series columns: `pressure_Pa`
      Json m = Json::object();
      for (std::size_t q = 0; q < quantities.size() && q < w.mean.size(); ++q)
        m.set(quantities[q].name + "_" + quantities[q].unit, w.mean[q]);
      return m;
    };
    Json windows = Json::array();
    const double y1 = c_.diagnostics.windows.bottom, area = window_cross_section(c_.grid);
    for (double h : c_.diagnostics.windows.heights)
    {
      const WindowStats w = window_stats(p, c_.grid.dim, y1, y1 + h, area);
      windows.push(Json::object().set("bottom_m", y1).set("height_m", h).set("particles", static_cast<long long>(w.count))
                       .set("bulk_density_kg_m3", w.bulk_density).set("means", means(w)));
    }
    const std::string per = units::si::per_missing_dimensions_column(c_.grid.dim);  // totals: per m in 2D
    Json r = Json::object();
    r.set("kinetic_energy_J" + per, t.kinetic)
        .set("internal_energy_J" + per, t.internal)
        .set("total_energy_J" + per, t.total())
        .set("momentum_kg_m_s" + per, Json::Array{t.momentum[0], t.momentum[1], t.momentum[2]})
        .set("means_all_particles", means(window_stats(p, c_.grid.dim, -INFINITY, INFINITY, 1.0)))
        .set("bottom_windows", std::move(windows));
    if (hugoniot_) r.set("hugoniot", hugoniot_json());
    return r;
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"solver.end_time", "output.*_interval", "output.thermo_every", "output.checkpoint_every"};
  }

 private:
  std::optional<CavityTracker> make_tracker() const {
    std::optional<CavityTracker> tracker;
    if (sample_.cavity) tracker.emplace(c_.grid.dim, *sample_.cavity, sample_.cavity_spacing);
    return tracker;
  }
  void open(RunContext& run, std::optional<ResumePoint> resume, std::optional<CavityTracker> tracker) {
    folder_ = run.folder;
    log_ = &run.log;
    output_.emplace(run.folder, c_, std::move(tracker), resume);
    start_time_ = sim_.time();
  }
  // The shock-front tool's result for summary.json: its file, the speeds and the plateau's means
  // keyed as the series columns.
  Json hugoniot_json() const {
    const std::vector<WindowQuantity> quantities = window_quantities(c_.grid.dim);
    const auto wave = [&](const WaveState& w) {
      Json plateau = Json::object();
      for (std::size_t q = 0; q < quantities.size() && q < w.plateau.size(); ++q)
        plateau.set(quantities[q].name + "_" + quantities[q].unit, w.plateau[q].mean);
      return Json::object().set("us_m_s", w.us).set("us_stderr_m_s", w.us_stderr).set("up_m_s", w.up)
          .set("density_rankine_hugoniot_kg_m3", w.density_rh).set("longitudinal_stress_rankine_hugoniot_Pa", w.stress_rh)
          .set("plateau", std::move(plateau));
    };
    Json j = Json::object().set("file", output_->hugoniot_file()->filename().string())
                 .set("complete", hugoniot_->complete()).set("shock", wave(hugoniot_->shock));
    if (hugoniot_->precursor) j.set("precursor", wave(*hugoniot_->precursor));
    return j.set("note", hugoniot_->note);
  }
  void log_plan() const {
    for (const std::string& note : c_.material_notes) log_->info("material file: {}", note);
    const std::size_t bodies = c_.bodies.size() * (c_.loading == LoadingKind::Symmetric ? 2 : 1);
    if (!c_.options.contact.enabled && bodies > 1)
      log_->info("{} bodies share one grid velocity field and stay glued where they meet; [contact] enabled = true "
                 "lets them separate and slide (docs/mpm.md)", bodies);
    if (c_.options.contact.enabled && bodies < 2) log_->info("[contact] is on but there is one body: nothing to do");
    log_->info("running to t = {} s; initial dt = {} s (about {} steps)", c_.end_time, first_dt_, steps_left());
  }

  // Output schedule: series row k at k·series_interval, field frame k at k·field_interval, the
  // listed histogram times. Steps are shortened to land on each of them (and on end_time).
  double next_event() const {
    const auto& hist = c_.diagnostics.histogram_times;
    double next = std::min(c_.end_time, static_cast<double>(counters_.series) * c_.output.series_interval);
    if (c_.output.field_interval > 0)
      next = std::min(next, static_cast<double>(counters_.fields) * c_.output.field_interval);
    if (static_cast<std::size_t>(counters_.histograms) < hist.size())
      next = std::min(next, hist[static_cast<std::size_t>(counters_.histograms)]);
    return next;
  }
  void write_due() {
    const double t = sim_.time() + tol_;
    const auto& hist = c_.diagnostics.histogram_times;
    write_due_frames(counters_.series, c_.output.series_interval, t, [&](auto) { output_->write_series(sim_); });
    write_due_frames(counters_.fields, c_.output.field_interval, t, [&](auto) { output_->write_fields(sim_); });
    for (; static_cast<std::size_t>(counters_.histograms) < hist.size() &&
           hist[static_cast<std::size_t>(counters_.histograms)] <= t;
         ++counters_.histograms)
      output_->write_histograms(sim_, static_cast<std::size_t>(counters_.histograms));
  }

  MpmCase c_;
  BuiltSample sample_;
  Simulation sim_;
  double first_dt_, tol_, start_time_ = 0.0;
  OutputCounters counters_;
  std::optional<RunOutput> output_;
  fs::path folder_;
  Logger* log_ = nullptr;
  std::optional<ShockHugoniot> hugoniot_;  ///< [shock_front]'s result, once the run has ended
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options) {
  return std::make_unique<MpmMethod>(root, options);
}

void run_case(const Config& root, const RunOptions& options) { run_method(root, options, &make_method); }

}  // namespace shockfield::mpm
