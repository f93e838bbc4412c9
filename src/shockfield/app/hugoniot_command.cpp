// `shockfield hugoniot CASE.toml --speeds 0.5,1,1.5,2`: a U_s–U_p sweep (md/hugoniot_sweep.hpp)
// with a table of the points and the fitted c0, s beside experimental copper (Marsh 1980).
#include <fmt/format.h>
#include <omp.h>

#include <cstdio>

#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/md/hugoniot_sweep.hpp"

namespace shockfield::app {
namespace {

struct HugoniotOptions {
  md::HugoniotSweepSettings sweep;
  std::vector<double> pressures;  ///< GPa, --method nphug
  std::optional<std::filesystem::path> output;
  int threads = 0;
};

void run(HugoniotOptions o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  o.sweep.folder = o.output.value_or(std::filesystem::path("runs") / (o.sweep.case_file.stem().string() + "_hugoniot"));
  if (o.sweep.method == "nphug" ? !o.pressures.empty() == !o.sweep.speeds.empty() || o.pressures.empty()
                                 : o.sweep.speeds.empty() || !o.pressures.empty())
    throw InputError(o.sweep.method == "nphug" ? "hugoniot --method nphug: give --pressures (GPa), not --speeds"
                                               : fmt::format("hugoniot --method {}: give --speeds (km/s), not --pressures",
                                                             o.sweep.method));
  if (o.sweep.method == "nphug") o.sweep.speeds = o.pressures;
  const md::HugoniotSweep sweep = md::run_hugoniot_sweep(o.sweep);
  std::printf("\n %s    Up (km/s)  Us (km/s)            P (GPa)  rho0 Us Up (GPa)  T (K)\n",
              o.sweep.method == "nphug" ? "P (GPa)" : o.sweep.method == "msst" ? "Us set " : "piston ");
  for (const md::SweepPoint& p : sweep.points)
    std::printf(" %6.3f   %9.4f  %9.4f +- %.4f  %7.2f  %16.2f  %5.0f\n", p.piston, p.up, p.us, p.us_stderr,
                p.pressure, p.pressure_rh, p.temperature);
  const std::string folder = o.sweep.folder.string();
  if (!sweep.fit) {
    std::printf("one speed: no Us-Up fit (give two or more speeds) -> %s/hugoniot_sweep.csv\n", folder.c_str());
    return;
  }
  const md::UsUpFit& f = *sweep.fit;
  std::printf("\nUs = c0 + s Up    this sweep           experiment, copper (Marsh 1980)\n"
              "c0 (km/s)         %.3f +- %.3f        %.3f\n"
              "s                 %.3f +- %.3f        %.3f\n"
              "-> %s/hugoniot_sweep.csv, %s/hugoniot_fit.toml; draw: shockfield plot hugoniot %s\n",
              f.c0(), f.line.intercept_stderr, md::kCopperC0, f.s(), f.line.slope_stderr, md::kCopperS,
              folder.c_str(), folder.c_str(), folder.c_str());
}

}  // namespace

void add_hugoniot_command(CLI::App& app) {
  auto o = std::make_shared<HugoniotOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hugoniot",
      "Us-Up sweep: run an MD case with one piston stage once per piston speed and fit the Hugoniot;\n"
      "with --method msst one msst stage once per shock speed, with --method nphug one nphug stage once\n"
      "per pressure (--pressures, GPa; run folders RUN/us_<speed>/, RUN/p_<GPa>/; their Hugoniot\n"
      "states are the stage's second-half means, with no U_s standard error).\n"
      "Each speed replaces `speed` of the case's [stage.piston] and runs into RUN/up_<speed>/ (a\n"
      "finished run there, with its hugoniot_<stage>.toml, is reused unless --overwrite). From each\n"
      "run's Hugoniot state (front = where the particle velocity passes half the piston speed; Us =\n"
      "slope of the front position over the last 70% of the stage, Up = mean particle velocity\n"
      "between piston and front) the sweep writes\n"
      "  RUN/hugoniot_sweep.csv  piston speed, Up, Us and its standard error from the front-fit\n"
      "                          residuals, pressure, density, temperature per run\n"
      "  RUN/hugoniot_fit.toml   Us = c0 + s Up by least squares with standard errors, and the\n"
      "                          experimental copper values (c0 = 3.94 km/s, s = 1.489; Marsh 1980)\n"
      "and prints c0 and s beside experiment. Draw it with `shockfield plot hugoniot RUN`.\n"
      "Example: shockfield hugoniot examples/md_shock_piston/case.toml --speeds 0.5,1.0,1.5,2.0");
  cmd->add_option("case", o->sweep.case_file,
                  "MD case file (TOML) with exactly one [stage.piston] (method piston) or one stage of ensemble "
                  "msst or nphug (method msst, nphug)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", o->sweep.method,
                  "piston (a piston-driven shock per piston speed), msst (an MSST cell per shock speed) or nphug "
                  "(a Hugoniostat cell per pressure)")
      ->check(CLI::IsMember({"piston", "msst", "nphug"}))
      ->default_val("piston");
  cmd->add_option("--speeds", o->sweep.speeds,
                  "Piston speeds (piston) or shock speeds (msst), km/s, comma-separated (e.g. 0.5,1.0,1.5,2.0)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cmd->add_option("--pressures", o->pressures, "Hugoniot pressures (nphug), GPa, comma-separated (e.g. 20,50,80)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cmd->add_option("-o,--output", o->output, "Sweep folder RUN (default: runs/<case file name>_hugoniot)");
  cmd->add_flag("--overwrite", o->sweep.overwrite, "Rerun every speed, replacing runs already in RUN");
  cmd->add_option("-j,--threads", o->threads, "OpenMP threads (default: OMP_NUM_THREADS, else all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("-q,--quiet", o->sweep.quiet, "No progress lines");
  cmd->callback([o] { run(*o); });
}

}  // namespace shockfield::app
