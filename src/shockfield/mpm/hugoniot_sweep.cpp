#include "shockfield/mpm/hugoniot_sweep.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/core/sweep_run.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/mpm/case_file.hpp"
#include "shockfield/mpm/run_case.hpp"

namespace shockfield::mpm {

namespace fs = std::filesystem;

namespace {

// The swept body's material, read from the case as a run reads it.
const materials::SolidMaterial& swept_material(const fs::path& case_file, MpmCase& c) {
  const Config root = Config::load(case_file);
  if (root.get_string_or("method", "") != "mpm")
    throw InputError(fmt::format("{}: hugoniot --method mpm needs an MPM case (method = \"mpm\")", case_file.string()));
  c = read_mpm_case(root);
  if (c.loading != LoadingKind::Wall && c.loading != LoadingKind::Symmetric)
    throw InputError(fmt::format("{}: a Hugoniot sweep sets [loading] speed: give [loading] type \"wall\" or "
                                 "\"symmetric\" (u_p is then the loading speed)", case_file.string()));
  if (!c.shock_front)
    throw InputError(fmt::format("{}: a Hugoniot sweep reads the shock-front tool's state: add [shock_front] "
                                 "(docs/mpm.md)", case_file.string()));
  const auto body = static_cast<std::size_t>(c.shock_front->settings.body);
  return c.materials[static_cast<std::size_t>(c.bodies[body].body.material)];
}

MpmSweepPoint run_one(const fs::path& case_file, const std::string& material, double speed, const fs::path& folder,
                      bool overwrite, bool quiet) {
  RunOptions r;
  r.case_file = case_file;
  r.output = folder;
  r.overwrite = overwrite;
  r.quiet = quiet;
  r.overrides.push_back(fmt::format("loading.speed={}", speed));
  const Config h =
      sweep_point_state(folder / fmt::format("hugoniot_{}.toml", material), r, "mpm", run_case, fmt::format("{} m/s", speed));
  MpmSweepPoint p;
  p.speed = speed;
  p.up = h.get_double("up_m_s");
  p.us = h.get_double("us_m_s");
  p.us_stderr = h.get_double("us_stderr_m_s");
  p.stress = h.get_double("longitudinal_stress_Pa");
  p.stress_rh = h.get_double("longitudinal_stress_rankine_hugoniot_Pa");
  p.density = h.get_double("bulk_density_kg_m3");
  p.density_rh = h.get_double("density_rankine_hugoniot_kg_m3");
  p.temperature = h.get_double("temperature_K");
  return p;
}

}  // namespace

MpmHugoniotSweep run_mpm_hugoniot_sweep(const fs::path& case_file, std::vector<double> speeds, const fs::path& folder,
                                        bool overwrite, bool quiet) {
  std::sort(speeds.begin(), speeds.end());
  if (speeds.empty() || speeds.front() <= 0) throw InputError("Hugoniot sweep: give positive loading speeds");
  if (std::adjacent_find(speeds.begin(), speeds.end()) != speeds.end())
    throw InputError("Hugoniot sweep: one of the speeds is given twice");
  MpmCase c;
  const materials::SolidMaterial& m = swept_material(case_file, c);
  MpmHugoniotSweep sweep;
  sweep.material = c.material_names[static_cast<std::size_t>(
      c.bodies[static_cast<std::size_t>(c.shock_front->settings.body)].body.material)];
  sweep.c0 = m.eos.c0, sweep.lambda = m.eos.lambda;
  fs::create_directories(folder);
  for (double v : speeds)
    sweep.points.push_back(run_one(case_file, sweep.material, v, folder / fmt::format("up_{}", v / 1000.0), overwrite, quiet));
  io::CsvWriter csv(folder / "hugoniot_sweep.csv",
                    {"loading_speed_m_s", "up_m_s", "us_m_s", "us_stderr_m_s", "longitudinal_stress_Pa",
                     "longitudinal_stress_rankine_hugoniot_Pa", "bulk_density_kg_m3",
                     "density_rankine_hugoniot_kg_m3", "temperature_K"});
  std::vector<double> up, us;
  for (const MpmSweepPoint& p : sweep.points) {
    csv.row({p.speed, p.up, p.us, p.us_stderr, p.stress, p.stress_rh, p.density, p.density_rh, p.temperature});
    up.push_back(p.up), us.push_back(p.us);
  }
  if (sweep.points.size() < 2) return sweep;
  sweep.fit = analysis::fit_us_up(up, us);
  const analysis::LineFit& f = sweep.fit->line;
  write_file_atomically(
      folder / "hugoniot_fit.toml",
      fmt::format("# U_s = c0 + s u_p, least squares; standard errors from the residuals (n - 2 dof)\n"
                  "c0_m_s = {}\nc0_stderr_m_s = {}\ns = {}\ns_stderr = {}\nresidual_rms_m_s = {}\npoints = {}\n"
                  "\n[material]  # the linear Hugoniot of {}'s Mie-Grueneisen EOS (c0, lambda)\nc0_m_s = {}\ns = {}\n",
                  f.intercept, f.intercept_stderr, f.slope, f.slope_stderr, f.residual_rms, f.points, sweep.material,
                  sweep.c0, sweep.lambda));
  return sweep;
}

}  // namespace shockfield::mpm
