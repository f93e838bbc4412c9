#include "shockfield/mpm/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/mpm/case_builder.hpp"
#include "shockfield/mpm/case_file.hpp"
#include "shockfield/mpm/checkpoint.hpp"
#include "shockfield/mpm/run_output.hpp"

namespace shockfield::mpm {

namespace fs = std::filesystem;

namespace {

struct Prepared {
  MpmCase c;
  BuiltSample sample;
  double first_dt = 0.0;
};

// Resolved values the run echoes under [derived] (seed §2.2.2 step; shock state of the linear
// Us-Up Hugoniot for the loading speed).
void derive(const Config& root, const Prepared& p, const Simulation& sim) {
  const MpmCase& c = p.c;
  root.derive("particles", static_cast<long long>(sim.particles().size()));
  root.derive("grid_nodes", static_cast<long long>(sim.grid().size()));
  root.derive("time_step_initial_s", p.first_dt);
  root.derive("estimated_steps", static_cast<long long>(std::ceil(c.end_time / p.first_dt)));
  for (std::size_t k = 0; k < p.sample.stats.size(); ++k)
    if (c.bodies[k].pores || c.bodies[k].cavity)
      root.derive(fmt::format("body{}_porosity", k), p.sample.stats[k].porosity());
  for (const auto& m : c.materials) {
    root.derive(m.name + "_longitudinal_speed_m_s", m.longitudinal_speed(m.eos.rho0, 0.0));
    root.derive(m.name + "_bulk_sound_speed_m_s", m.eos.c0);
  }
  if (c.loading == LoadingKind::Wall || c.loading == LoadingKind::Symmetric) {
    const auto& eos = c.materials[static_cast<std::size_t>(c.bodies[0].body.material)].eos;
    const double up = c.speed, us = eos.shock_speed(up);
    root.derive("hugoniot_shock_speed_m_s", us);
    root.derive("hugoniot_pressure_Pa", eos.rho0 * us * up);
    root.derive("hugoniot_density_kg_m3", eos.rho0 * us / (us - up));
  }
  root.derive("openmp_threads", static_cast<long long>(omp_get_max_threads()));
}

// NaN, negative density: the step that went wrong is named, the outputs are kept.
void check_health(const Simulation& sim) {
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double rho = p.density(i);
    if (!p.x[i].allFinite() || !p.v[i].allFinite() || !std::isfinite(p.state[i].pressure))
      throw RunError(fmt::format("mpm: particle {} has a non-finite position, velocity or pressure at t = {} s (step {})",
                                 i, sim.time(), sim.step_count()));
    if (!(rho > 0.0))
      throw RunError(fmt::format("mpm: particle {} has density {} kg/m^3 at t = {} s (step {})", i, rho, sim.time(),
                                 sim.step_count()));
  }
}

// One step; a fixed time step is checked against the CFL limit Δx/max(c_p + |v_p|) (and the
// diffusion limit with heat conduction) first.
void advance(Simulation& sim, const MpmCase& c, double max_dt) {
  if (c.time_step) {
    const double limit = sim.stable_time_step();  // courant = 1 for fixed steps
    if (*c.time_step > limit)
      throw RunError(fmt::format("mpm: time_step {} s is beyond the CFL limit {} s = dx / max(c + |v|) (or dx²/(2dα) "
                                 "with heat_conduction) at t = {} s "
                                 "(step {}); lower [solver] time_step or drop it for the adaptive step",
                                 *c.time_step, limit, sim.time(), sim.step_count()));
    max_dt = std::min(max_dt, *c.time_step);
  }
  sim.step(max_dt);
}

}  // namespace

void run_case(const Config& root, const RunOptions& options) {
  Prepared p;
  p.c = read_mpm_case(root);
  p.sample = build_sample(p.c, root);
  root.check_unknown_keys();
  const MpmCase& c = p.c;
  Simulation sim(c.grid, c.materials, std::move(p.sample.particles), c.options);
  p.first_dt = c.time_step.value_or(sim.stable_time_step());
  if (c.time_step && *c.time_step > sim.stable_time_step())
    root.table("solver").fail("time_step", fmt::format("{} s is beyond the CFL limit {} s = dx / max(c + |v|) (or "
                                                       "dx²/(2dα) with heat_conduction) of the initial state", *c.time_step, sim.stable_time_step()));
  derive(root, p, sim);
  if (options.validate_only) {
    std::printf("%s: valid mpm case (%zu particles, %zu grid nodes, dt %.3g s)\n", options.case_file.string().c_str(),
                sim.particles().size(), sim.grid().size(), p.first_dt);
    return;
  }

  RunSession run = open_run_session(
      root, options, "mpm",
      fmt::format("{} particles, {} grid nodes, {}D", sim.particles().size(), sim.grid().size(), c.grid.dim));
  const fs::path& folder = run.folder;
  const fs::path& checkpoint = run.checkpoint;
  Logger& log = run.log;

  std::optional<CavityTracker> tracker;
  if (p.sample.cavity) tracker.emplace(c.grid.dim, *p.sample.cavity, p.sample.cavity_spacing);
  OutputCounters counters;
  std::optional<ResumePoint> resume;
  if (options.resume) {
    if (!fs::exists(checkpoint)) throw InputError(fmt::format("--resume: no checkpoint in '{}'", folder.string()));
    std::vector<double> cavity_state;
    counters = read_checkpoint(checkpoint, sim, cavity_state);
    if (tracker && !cavity_state.empty()) tracker->restore(cavity_state);
    resume = ResumePoint{sim.step_count(), sim.time()};
    log.info("resumed from {} at step {}, t = {} s", checkpoint.string(), sim.step_count(), sim.time());
  }
  RunOutput output(folder, c, std::move(tracker), resume);

  // Output schedule: series row k at k·series_interval, field frame k at k·field_interval, the
  // listed histogram times. Steps are shortened to land on each of them (and on end_time).
  const double tol = 1e-9 * c.end_time;
  const auto& hist_times = c.diagnostics.histogram_times;
  auto next_event = [&] {
    double next = std::min(c.end_time, static_cast<double>(counters.series) * c.output.series_interval);
    if (c.output.field_interval > 0) next = std::min(next, static_cast<double>(counters.fields) * c.output.field_interval);
    if (static_cast<std::size_t>(counters.histograms) < hist_times.size())
      next = std::min(next, hist_times[static_cast<std::size_t>(counters.histograms)]);
    return next;
  };
  auto write_due = [&] {
    const double t = sim.time() + tol;
    write_due_frames(counters.series, c.output.series_interval, t, [&](auto) { output.write_series(sim); });
    write_due_frames(counters.fields, c.output.field_interval, t, [&](auto) { output.write_fields(sim); });
    for (; static_cast<std::size_t>(counters.histograms) < hist_times.size() &&
           hist_times[static_cast<std::size_t>(counters.histograms)] <= t;
         ++counters.histograms)
      output.write_histograms(sim, static_cast<std::size_t>(counters.histograms));
  };
  auto cavity_state = [&] { return output.cavity() ? output.cavity()->state() : std::vector<double>{}; };

  clear_stop_request();
  install_stop_handlers();
  if (!options.resume) write_due();
  const long first = sim.step_count();
  const auto remaining = static_cast<std::int64_t>(std::ceil((c.end_time - sim.time()) / p.first_dt));
  Progress progress("mpm", first, remaining, !options.quiet);
  const double start_time = sim.time();
  log.info("running to t = {} s; initial dt = {} s (about {} steps)", c.end_time, p.first_dt, remaining);
  try {
    while (sim.time() < c.end_time - tol) {
      advance(sim, c, next_event() - sim.time());
      check_health(sim);
      write_due();
      progress.update(sim.step_count(), (sim.time() - start_time) / (c.end_time - start_time));
      if (c.output.checkpoint_every > 0 && sim.step_count() % c.output.checkpoint_every == 0)
        write_checkpoint(checkpoint, sim, counters, cavity_state());
      if (stop_requested() || (options.stop_after > 0 && sim.step_count() - first == options.stop_after)) {
        progress.finish(sim.step_count());
        write_checkpoint(checkpoint, sim, counters, cavity_state());
        log.info("stopped at step {} (t = {} s): checkpoint written to {}", sim.step_count(), sim.time(), checkpoint.string());
        throw StopRequested(fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                        sim.step_count(), options.case_file.string(), folder.string()));
      }
    }
  } catch (const RunError& e) {
    log.info("run stopped: {}", e.what());
    io::VtkArray none{"density", 1, {}};
    std::vector<double> xyz;
    for (const Vec3& x : sim.particles().x) xyz.insert(xyz.end(), {x[0], x[1], x[2]});
    for (std::size_t i = 0; i < sim.particles().size(); ++i) none.values.push_back(sim.particles().density(i));
    io::write_vtp(folder / "failure.vtp", xyz, {none}, io::VtkEncoding::Ascii);
    log.info("the output written so far is kept in {}; particles at the failure: failure.vtp", folder.string());
    throw;
  }
  progress.finish(sim.step_count());
  write_checkpoint(checkpoint, sim, counters, cavity_state());
  const Totals t = totals(sim.particles());
  log.info("finished: t = {} s after {} steps ({:.3g} particle-steps/s); energy {} J, momentum ({}, {}, {}) kg m/s",
           sim.time(), sim.step_count(),
           progress.rate(sim.step_count()) * static_cast<double>(sim.particles().size()), t.total(), t.momentum[0],
           t.momentum[1], t.momentum[2]);
}

}  // namespace shockfield::mpm
