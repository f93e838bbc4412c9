// `shockfield hugoniot CASE.toml --speeds 0.5,1,1.5,2`: a U_s–U_p sweep (md/hugoniot_sweep.hpp)
// with a table of the points and the fitted c0, s beside experimental copper (Marsh 1980); with
// --method mpm an MPM case's sweep over loading speeds (mpm/hugoniot_sweep.hpp) beside its
// material's linear Hugoniot.
#include <fmt/format.h>
#include <omp.h>

#include <cstdio>

#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/md/hugoniot_sweep.hpp"
#include "shockfield/mpm/hugoniot_sweep.hpp"

namespace shockfield::app {
namespace {

struct HugoniotOptions {
  md::HugoniotSweepSettings sweep;
  std::vector<double> pressures;  ///< GPa, --method nphug
  std::optional<std::filesystem::path> output;
  int threads = 0;
};

// The MPM sweep: loading speeds in km/s on the command line, SI in the files.
void run_mpm(const HugoniotOptions& o) {
  std::vector<double> speeds;
  for (double v : o.sweep.speeds) speeds.push_back(v * 1000.0);
  const mpm::MpmHugoniotSweep sweep =
      mpm::run_mpm_hugoniot_sweep(o.sweep.case_file, speeds, o.sweep.folder, o.sweep.overwrite, o.sweep.quiet);
  std::printf("\n loading    up (km/s)  Us (km/s)            -sigma_aa (GPa)  rho00 Us up (GPa)  T (K)\n");
  for (const mpm::MpmSweepPoint& p : sweep.points)
    std::printf(" %6.3f   %9.4f  %9.4f +- %.4f  %15.3f  %17.3f  %5.0f\n", p.speed / 1000.0, p.up / 1000.0,
                p.us / 1000.0, p.us_stderr / 1000.0, -p.stress / 1e9, -p.stress_rh / 1e9, p.temperature);
  const std::string folder = o.sweep.folder.string();
  if (!sweep.fit) {
    std::printf("one speed: no Us-up fit (give two or more speeds) -> %s/hugoniot_sweep.csv\n", folder.c_str());
    return;
  }
  const analysis::LineFit& f = sweep.fit->line;
  std::printf("\nUs = c0 + s up    this sweep           %s (its EOS)\n"
              "c0 (km/s)         %.3f +- %.3f        %.3f\n"
              "s                 %.3f +- %.3f        %.3f\n"
              "-> %s/hugoniot_sweep.csv, %s/hugoniot_fit.toml\n",
              sweep.material.c_str(), f.intercept / 1000.0, f.intercept_stderr / 1000.0, sweep.c0 / 1000.0, f.slope,
              f.slope_stderr, sweep.lambda, folder.c_str(), folder.c_str());
}

void run(HugoniotOptions o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  o.sweep.folder = o.output.value_or(std::filesystem::path("runs") / (o.sweep.case_file.stem().string() + "_hugoniot"));
  if (o.sweep.method == "mpm") {
    if (o.sweep.speeds.empty() || !o.pressures.empty())
      throw InputError("hugoniot --method mpm: give --speeds (loading speeds, km/s), not --pressures");
    run_mpm(o);
    return;
  }
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
  const analysis::UsUpFit& f = *sweep.fit;
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
      "With --method mpm an MPM case with wall or symmetric [loading] and [shock_front] runs once per\n"
      "loading speed (--speeds, km/s; u_p is the loading speed) into RUN/up_<speed>/, and the sweep\n"
      "fits its hugoniot_<material>.toml states (SI files) beside the material's linear Hugoniot.\n"
      "Example: shockfield hugoniot examples/md_shock_piston/case.toml --speeds 0.5,1.0,1.5,2.0");
  cmd->add_option("case", o->sweep.case_file,
                  "MD case file (TOML) with exactly one [stage.piston] (method piston) or one stage of ensemble "
                  "msst or nphug (method msst, nphug); an MPM case (method mpm)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", o->sweep.method,
                  "piston (a piston-driven shock per piston speed), msst (an MSST cell per shock speed), nphug "
                  "(a Hugoniostat cell per pressure) or mpm (an MPM impact per loading speed)")
      ->check(CLI::IsMember({"piston", "msst", "nphug", "mpm"}))
      ->default_val("piston");
  cmd->add_option("--speeds", o->sweep.speeds,
                  "Piston speeds (piston), shock speeds (msst) or loading speeds (mpm), km/s, comma-separated (e.g. "
                  "0.5,1.0,1.5,2.0)")
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
