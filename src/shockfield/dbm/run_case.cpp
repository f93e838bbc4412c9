#include "shockfield/dbm/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/checkpoint.hpp"
#include "shockfield/dbm/gls_run.hpp"
#include "shockfield/dbm/reaction.hpp"
#include "shockfield/dbm/reaction_case.hpp"
#include "shockfield/dbm/stability_case.hpp"
#include "shockfield/dbm/tne.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::dbm {

namespace fs = std::filesystem;

namespace {

// Indices of Δ*_2 xx and Δ*_(3,1) x in TneFields (order of kTneNames).
constexpr int kD2xx = 0, kD31x = 7;

void derive(const Config& root, const DbmCase& c, const Simulation& sim) {
  root.derive("cells", static_cast<long long>(c.lattice.nx) * c.lattice.ny);
  root.derive("degrees_of_freedom_b", sim.b());
  root.derive("max_speed", c.model.max_speed());
  root.derive("moment_condition_number", sim.inversion().condition_number());
  root.derive("time_step", c.bgk.dt);
  root.derive("steps", c.steps);
  root.derive("courant", c.model.max_speed() * c.bgk.dt / c.lattice.dx);
  root.derive("dt_over_tau", c.bgk.dt / c.bgk.tau);
  root.derive("openmp_threads", static_cast<long long>(omp_get_max_threads()));
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

// series.csv (domain means), profiles/ (line profiles along x at row profile_row) and fields/
// with grid.pvd. A resumed run keeps what was written up to its checkpoint and rewrites the rest.
class Output {
 public:
  /// `reaction`: the reactive DBM of a [reaction] case (extra columns), or null; `gls`: the
  /// liquid–vapour part of a kind = "gls" case (its own series columns), or null.
  Output(const fs::path& folder, const DbmOutputSpec& spec, const Simulation* resumed, const OutputCounters& counters,
         const ReactiveFlow* reaction, const std::optional<ReactionSpec>& spec_reaction, GlsRunPart* gls)
      : folder_(folder), row_(spec.profile_row), reaction_(reaction), spec_reaction_(spec_reaction), gls_(gls) {
    const double keep_step = resumed ? static_cast<double>(resumed->steps()) : 0.0;
    const double keep_profile = static_cast<double>(counters.profiles) - 1.0;
    std::vector<std::string> series_columns =
        gls ? GlsRunPart::series_columns() : std::vector<std::string>{"step", "time", "rho", "ux", "uy", "T", "D"};
    if (reaction_) series_columns.insert(series_columns.end(), {"lambda", "chemical_energy", "total_energy", "front_x"});
    series_ = io::CsvWriter(folder / "series.csv", series_columns, resumed ? &keep_step : nullptr);
    fs::create_directories(folder / "profiles");
    index_ = io::CsvWriter(folder / "profiles" / "index.csv", {"profile", "step", "time"},
                           resumed ? &keep_profile : nullptr);
    if (spec.field_interval > 0.0) {
      fs::create_directories(folder / "fields");
      const double keep_time = resumed ? resumed->time() : 0.0;
      grid_pvd_ = io::PvdSeries(folder / "grid.pvd", resumed ? &keep_time : nullptr);
    }
  }

  void write_series(const Simulation& sim) {
    if (gls_) return series_.row(gls_->series_row(sim));
    const Lattice& l = sim.lattice();
    double rho = 0, ux = 0, uy = 0, T = 0;
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) {
        const Macro m = sim.macro(i, j);
        rho += m.rho, ux += m.ux, uy += m.uy, T += m.T;
      }
    const double n = static_cast<double>(l.nx) * l.ny;
    std::vector<double> row{static_cast<double>(sim.steps()), sim.time(), rho / n, ux / n, uy / n, T / n,
                            tne_measures(sim).mean_strength};
    if (reaction_) {  // [reaction]: mean λ, Q·Σφ, E + Q·Σφ and the tracked front (detonation.hpp)
      double lambda = 0.0;
      for (int j = 0; j < l.ny; ++j)
        for (int i = 0; i < l.nx; ++i) lambda += reaction_->lambda(i, j);
      const double chemical = reaction_->chemical_energy();
      row.insert(row.end(), {lambda / n, chemical, sim.totals()[3] + chemical,
                             pressure_front(sim, row_, spec_reaction_->front_pressure())});
    }
    series_.row(row);
  }

  void write_profile(const Simulation& sim, std::int64_t index) {
    const TneFields tne = tne_measures(sim);
    const Lattice& l = sim.lattice();
    std::vector<std::string> columns{"x", "rho", "ux", "uy", "p", "T", "D2xx", "D31x"};
    if (reaction_) columns.insert(columns.end(), {"lambda", "omega"});
    io::CsvWriter csv(folder_ / "profiles" / fmt::format("profile_{}.csv", index), columns);
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = sim.macro(i, row_);
      const std::size_t cell = static_cast<std::size_t>(i) + static_cast<std::size_t>(l.nx) * row_;
      std::vector<double> row{l.x(i), m.rho, m.ux, m.uy, m.rho * m.T, m.T, tne.central[kD2xx][cell], tne.central[kD31x][cell]};
      if (reaction_) row.insert(row.end(), {reaction_->lambda(i, row_), reaction_->consumption(i, row_)});
      csv.row(row);
    }
    index_.row({static_cast<double>(index), static_cast<double>(sim.steps()), sim.time()});
  }

  /// ρ, u, T and the TNE strength D on the cell centres.
  void write_fields(const Simulation& sim) {
    const Lattice& l = sim.lattice();
    const std::size_t n = static_cast<std::size_t>(l.nx) * static_cast<std::size_t>(l.ny);
    io::VtkImage img;
    img.points = {static_cast<std::size_t>(l.nx), static_cast<std::size_t>(l.ny), 1};
    img.origin = {l.x(0), l.y(0), 0.0};
    img.spacing = {l.dx, l.dy, 1.0};
    std::vector<double> rho(n), u(3 * n), T(n);
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) {
        const Macro m = sim.macro(i, j);
        const std::size_t c = static_cast<std::size_t>(i) + static_cast<std::size_t>(l.nx) * static_cast<std::size_t>(j);
        rho[c] = m.rho, u[3 * c] = m.ux, u[3 * c + 1] = m.uy, T[c] = m.T;
      }
    img.point_data = {{"rho", 1, std::move(rho)}, {"velocity", 3, std::move(u)}, {"T", 1, std::move(T)}};
    if (gls_) {
      for (io::VtkArray& a : gls_->field_arrays()) img.point_data.push_back(std::move(a));
    } else {
      img.point_data.push_back({"D", 1, tne_measures(sim).strength});
    }
    const std::string file = fmt::format("fields/grid_{:09d}.vti", sim.steps());
    io::write_vti(folder_ / file, img, io::VtkEncoding::Ascii);
    grid_pvd_.add(sim.time(), file);
  }

 private:
  fs::path folder_;
  int row_;
  const ReactiveFlow* reaction_;
  const std::optional<ReactionSpec>& spec_reaction_;
  GlsRunPart* gls_;
  io::CsvWriter series_, index_;
  io::PvdSeries grid_pvd_;
};

}  // namespace

void run_case(const Config& root, const RunOptions& options) {
  const DbmCase c = read_dbm_case(root);
  // The linear check is for the BGK model; the GLS force is outside it (docs/theory/dbm.md).
  const CaseStability stability = c.gls ? CaseStability{} : check_case_stability(root.table("model"), c);
  root.check_unknown_keys();
  Simulation sim(c.model, c.lattice, c.boundaries, c.bgk);
  // [reaction]: the reactive DBM installs its source on sim (reaction.hpp).
  std::unique_ptr<ReactiveFlow> reaction =
      c.reaction ? std::make_unique<ReactiveFlow>(sim, c.boundaries, c.reaction->law, c.reaction->inflow_lambda)
                 : nullptr;
  std::vector<double>* reactant = reaction ? &reaction->reactant_density() : nullptr;
  std::optional<GlsRunPart> gls;
  if (c.gls) gls.emplace(sim, c);
  derive(root, c, sim);
  derive_stability(root, stability);
  if (options.validate_only) {
    std::printf("%s: valid dbm case (%d x %d cells, %lld steps, dt %.3g)\n", options.case_file.string().c_str(),
                c.lattice.nx, c.lattice.ny, c.steps, c.bgk.dt);
    return;
  }

  RunSession run = open_run_session(root, options, "dbm",
                                    fmt::format("{} x {} cells, D2V16{}, tau {}", c.lattice.nx, c.lattice.ny,
                                                c.gls ? ", GLS liquid-vapour" : "", c.bgk.tau));
  const fs::path& checkpoint = run.checkpoint;
  OutputCounters counters;
  if (options.resume) {
    if (!fs::exists(checkpoint))
      throw InputError(fmt::format("--resume: no checkpoint in '{}'", run.folder.string()));
    counters = read_checkpoint(checkpoint, sim, reactant);
    run.log.info("resumed from {} at step {}, t = {}", checkpoint.string(), sim.steps(), sim.time());
  } else if (gls) {
    gls->initialize(sim);
  } else {
    const InitialSpec& init = c.initial;
    const auto initial = [&](double x, double) { return x < init.split ? init.left : init.right; };
    if (reaction)
      initialize_detonation(sim, *reaction, c.reaction->ignition, c.reaction->theory, initial);
    else
      sim.initialize(initial);
  }
  Output output(run.folder, c.output, options.resume ? &sim : nullptr, counters, reaction.get(), c.reaction,
                gls ? &*gls : nullptr);

  // Rows and frames at the first step at or past k·interval.
  const double tol = 1e-9 * c.bgk.dt;
  auto write_due = [&] {
    const double t = sim.time() + tol;
    write_due_frames(counters.series, c.output.series_interval, t, [&](auto) { output.write_series(sim); });
    write_due_frames(counters.profiles, c.output.profile_interval, t, [&](auto k) { output.write_profile(sim, k); });
    write_due_frames(counters.fields, c.output.field_interval, t, [&](auto) { output.write_fields(sim); });
  };
  auto save = [&] { write_checkpoint(checkpoint, sim, counters, reactant); };

  clear_stop_request();
  install_stop_handlers();
  if (!options.resume) write_due();
  const long long first = sim.steps();
  Progress progress("dbm", first, c.steps - first, !options.quiet);
  run.log.info("running to t = {} in {} steps of dt = {} (tau = {}, Courant {:.3g})", c.end_time, c.steps, c.bgk.dt,
               c.bgk.tau, c.model.max_speed() * c.bgk.dt / c.lattice.dx);
  try {
    while (sim.steps() < c.steps) {
      sim.step();
      sim.check_state();
      write_due();
      progress.update(sim.steps(), sim.time() / c.end_time);
      if (c.output.checkpoint_every > 0 && sim.steps() % c.output.checkpoint_every == 0) save();
      if (stop_requested() || (options.stop_after > 0 && sim.steps() - first == options.stop_after)) {
        progress.finish(sim.steps());
        output.write_profile(sim, counters.profiles);
        save();
        run.log.info("stopped at step {} (t = {}): checkpoint written to {}, the state in profiles/profile_{}.csv",
                     sim.steps(), sim.time(), checkpoint.string(), counters.profiles);
        throw StopRequested(fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                        sim.steps(), options.case_file.string(), run.folder.string()));
      }
    }
  } catch (const RunError& e) {
    run.log.info("run stopped: {}", e.what());
    output.write_profile(sim, counters.profiles);
    run.log.info("the output written so far is kept in {}; the state at the failure: profiles/profile_{}.csv",
                 run.folder.string(), counters.profiles);
    if (gls) {
      run.log.info("{}", GlsRunPart::blow_up_hint());
      gls->write_summary(run.folder, run.log);
    }
    throw;
  }
  progress.finish(sim.steps());
  if (c.output.profile_interval == 0.0) output.write_profile(sim, counters.profiles++);
  save();
  if (gls) gls->write_summary(run.folder, run.log);
  const auto total = sim.totals();
  run.log.info("finished: t = {} after {} steps ({:.3g} cell-steps/s); mass {}, momentum ({}, {}), energy {}",
               sim.time(), sim.steps(), progress.rate(sim.steps()) * c.lattice.nx * c.lattice.ny, total[0], total[1],
               total[2], total[3]);
  if (reaction)
    run.log.info("chemical energy Q*sum(rho*lambda) {}; energy + chemical energy {}", reaction->chemical_energy(),
                 total[3] + reaction->chemical_energy());
}

}  // namespace shockfield::dbm
