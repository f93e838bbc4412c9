#include "shockfield/dbm/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cstdio>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/tne.hpp"
#include "shockfield/io/csv_writer.hpp"

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
}

// series.csv (domain means) and profiles/ (line profiles along x at row profile_row).
class Output {
 public:
  Output(const fs::path& folder, int row)
      : folder_(folder / "profiles"),
        row_(row),
        series_(folder / "series.csv", {"step", "time", "rho", "ux", "uy", "T", "D"}) {
    fs::create_directories(folder_);
    index_ = io::CsvWriter(folder_ / "index.csv", {"profile", "step", "time"});
  }

  void write_series(const Simulation& sim) {
    const Lattice& l = sim.lattice();
    double rho = 0, ux = 0, uy = 0, T = 0;
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) {
        const Macro m = sim.macro(i, j);
        rho += m.rho, ux += m.ux, uy += m.uy, T += m.T;
      }
    const double n = static_cast<double>(l.nx) * l.ny;
    series_.row({static_cast<double>(sim.steps()), sim.time(), rho / n, ux / n, uy / n, T / n,
                 tne_measures(sim).mean_strength});
  }

  void write_profile(const Simulation& sim) {
    const TneFields tne = tne_measures(sim);
    const Lattice& l = sim.lattice();
    io::CsvWriter csv(folder_ / fmt::format("profile_{}.csv", profiles_),
                      {"x", "rho", "ux", "uy", "p", "T", "D2xx", "D31x"});
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = sim.macro(i, row_);
      const std::size_t cell = static_cast<std::size_t>(i) + static_cast<std::size_t>(l.nx) * row_;
      csv.row({l.x(i), m.rho, m.ux, m.uy, m.rho * m.T, m.T, tne.central[kD2xx][cell], tne.central[kD31x][cell]});
    }
    index_.row({static_cast<double>(profiles_++), static_cast<double>(sim.steps()), sim.time()});
  }
  long long profiles() const { return profiles_; }

 private:
  fs::path folder_;
  int row_;
  io::CsvWriter series_, index_;
  long long profiles_ = 0;
};

}  // namespace

void run_case(const Config& root, const RunOptions& options) {
  const DbmCase c = read_dbm_case(root);
  root.check_unknown_keys();
  if (options.resume)
    throw InputError("--resume: dbm runs cannot be resumed yet (they write no checkpoint); rerun the case with "
                     "--overwrite");
  Simulation sim(c.model, c.lattice, c.boundaries, c.bgk);
  derive(root, c, sim);
  if (options.validate_only) {
    std::printf("%s: valid dbm case (%d x %d cells, %lld steps, dt %.3g)\n", options.case_file.string().c_str(),
                c.lattice.nx, c.lattice.ny, c.steps, c.bgk.dt);
    return;
  }

  RunSession run = open_run_session(root, options, "dbm",
                                    fmt::format("{} x {} cells, D2V16, tau {}", c.lattice.nx, c.lattice.ny, c.bgk.tau));
  const InitialSpec& init = c.initial;
  sim.initialize([&](double x, double) { return x < init.split ? init.left : init.right; });
  Output output(run.folder, c.output.profile_row);

  // Rows at the first step at or past k·interval.
  long long series = 0, profiles = 0;
  const double tol = 1e-9 * c.bgk.dt;
  auto write_due = [&] {
    const double t = sim.time() + tol;
    for (; static_cast<double>(series) * c.output.series_interval <= t; ++series) output.write_series(sim);
    for (; c.output.profile_interval > 0 && static_cast<double>(profiles) * c.output.profile_interval <= t; ++profiles)
      output.write_profile(sim);
  };

  clear_stop_request();
  install_stop_handlers();
  write_due();
  Progress progress("dbm", 0, c.steps, !options.quiet);
  run.log.info("running to t = {} in {} steps of dt = {} (tau = {}, Courant {:.3g})", c.end_time, c.steps, c.bgk.dt,
               c.bgk.tau, c.model.max_speed() * c.bgk.dt / c.lattice.dx);
  try {
    while (sim.steps() < c.steps) {
      sim.step();
      sim.check_state();
      write_due();
      progress.update(sim.steps(), sim.time() / c.end_time);
      if (stop_requested() || (options.stop_after > 0 && sim.steps() == options.stop_after)) {
        progress.finish(sim.steps());
        output.write_profile(sim);
        run.log.info("stopped at step {} (t = {}); the output so far is kept", sim.steps(), sim.time());
        throw StopRequested(fmt::format("stopped at step {} (t = {}); dbm runs cannot be resumed yet: rerun with "
                                        "--overwrite to start again",
                                        sim.steps(), sim.time()));
      }
    }
  } catch (const RunError& e) {
    run.log.info("run stopped: {}", e.what());
    output.write_profile(sim);
    run.log.info("the output written so far is kept in {}; the state at the failure: profiles/profile_{}.csv",
                 run.folder.string(), output.profiles() - 1);
    throw;
  }
  progress.finish(sim.steps());
  if (c.output.profile_interval == 0.0) output.write_profile(sim);
  const auto total = sim.totals();
  run.log.info("finished: t = {} after {} steps ({:.3g} cell-steps/s); mass {}, momentum ({}, {}), energy {}",
               sim.time(), sim.steps(), progress.rate(sim.steps()) * c.lattice.nx * c.lattice.ny, total[0], total[1],
               total[2], total[3]);
}

}  // namespace shockfield::dbm
