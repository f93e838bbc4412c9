#include "shockfield/md/hugoniot_sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/core/sweep_run.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/run_case.hpp"

namespace shockfield::md {

namespace fs = std::filesystem;
using units::metal::A_per_ps_to_km_per_s;

namespace {

// The one stage of the sweep's method (a [stage.piston], or ensemble msst or nphug) and its index;
// a piston sweep needs profiles for the front to be tracked.
std::pair<std::string, std::size_t> sweep_stage(const fs::path& case_file, const std::string& method) {
  const Config root = Config::load(case_file);
  root.get_choice("method", {"md"});
  const MdCase mdcase = read_md_case(root);
  std::vector<std::size_t> found;
  for (std::size_t k = 0; k < mdcase.stages.size(); ++k)
    if (method == "piston" ? mdcase.stages[k].piston.has_value() : mdcase.stages[k].ensemble == method) found.push_back(k);
  if (found.size() != 1)
    throw InputError(fmt::format("{}: a Hugoniot sweep with --method {} needs exactly one [[stage]] {}, found {}",
                                 case_file.string(), method,
                                 method == "piston" ? "with a [stage.piston]" : "with ensemble = \"" + method + "\"",
                                 found.size()));
  if (method == "piston" && mdcase.output.profile_every == 0)
    throw InputError(fmt::format("{}: a Hugoniot sweep needs profiles: set [output] profile_every > 0",
                                 case_file.string()));
  return {mdcase.stages[found.front()].name, found.front()};
}

// The run folder's name and the RunOptions of one value of the sweep.
std::string value_folder(const std::string& method, double value) {
  if (method == "msst") return fmt::format("us_{:.2f}", value);
  if (method == "nphug") return fmt::format("p_{:.2f}", value);
  return fmt::format("up_{:.2f}", value);
}

void set_value(RunOptions& r, const std::string& method, std::size_t stage, double value) {
  if (method == "msst") r.overrides.push_back(fmt::format("stage[{}].msst.shock_speed={}", stage, value / A_per_ps_to_km_per_s));
  else if (method == "nphug") r.overrides.push_back(fmt::format("stage[{}].nphug.pressure={}", stage, value / units::metal::bar_to_GPa));
  else r.piston_speed = value / A_per_ps_to_km_per_s;
}

// shock_front_<stage>.csv: step, time_ps, front_A, piston_A ("nan" where no front was found).
// Every time and front position is checked where it is read (file:line): finite (a front may be
// the "nan" of no front) and within kMaxMagnitude, so that the fit's sums cannot overflow to inf.
analysis::LineFit front_fit(const fs::path& file) {
  constexpr double kMaxMagnitude = 1e9;  // ps or Å: 1 ms, 10 cm — far beyond any MD run
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open", name));
  std::string line;
  std::getline(in, line);
  std::vector<double> t, x;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::stringstream ss(line);
    std::string step, time, front;
    if (!std::getline(ss, step, ',') || !std::getline(ss, time, ',') || !std::getline(ss, front, ','))
      throw InputError(fmt::format("{}:{}: expected 'step,time_ps,front_A,piston_A', found '{}'", name, number, line));
    const auto value = [&](const std::string& word, const char* what, bool nan_allowed) {
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      const bool whole = end != word.c_str() && *end == '\0';
      if (!whole || !(std::abs(v) <= kMaxMagnitude || (nan_allowed && std::isnan(v))))
        throw InputError(fmt::format("{}:{}: expected a {} of magnitude at most {:g}, found '{}'", name, number, what,
                                     kMaxMagnitude, word));
      return v;
    };
    t.push_back(value(time, "time in ps", false));
    x.push_back(value(front, "front position in Å (or nan)", true));
  }
  try {
    return analysis::fit_shock_front(t, x);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", name, e.what()));
  }
}

SweepPoint run_one(const HugoniotSweepSettings& s, double value, const fs::path& folder,
                   const std::pair<std::string, std::size_t>& stage) {
  RunOptions r;
  r.case_file = s.case_file;
  r.output = folder;
  r.overwrite = s.overwrite;
  r.quiet = s.quiet;
  set_value(r, s.method, stage.second, value);
  const Config h = sweep_point_state(folder / fmt::format("hugoniot_{}.toml", stage.first), r, "md", run_case,
                                     value_folder(s.method, value));
  SweepPoint p;
  p.piston = s.method == "piston" ? h.get_double("piston_speed_km_s") : value;
  p.up = h.get_double("up_km_s");
  p.us = h.get_double("us_km_s");
  p.pressure = h.get_double("pressure_GPa");
  p.pressure_rh = h.get_double("pressure_rankine_hugoniot_GPa");
  p.density = h.get_double("density_g_cc");
  p.temperature = h.get_double("temperature_K");
  if (s.method != "piston") {  // a time-averaged state: no front to fit
    p.us_stderr = p.front_rms = NAN;
    return p;
  }
  const analysis::LineFit f = front_fit(folder / fmt::format("shock_front_{}.csv", stage.first));
  p.us_stderr = f.slope_stderr * A_per_ps_to_km_per_s;
  p.front_rms = f.residual_rms;
  return p;
}

}  // namespace

HugoniotSweep run_hugoniot_sweep(HugoniotSweepSettings s) {
  const char* what = s.method == "nphug" ? "pressures" : s.method == "msst" ? "shock speeds" : "piston speeds";
  if (s.speeds.empty()) throw InputError(fmt::format("Hugoniot sweep: no {}", what));
  std::sort(s.speeds.begin(), s.speeds.end());
  if (s.speeds.front() <= 0) throw InputError(fmt::format("Hugoniot sweep: {} must be positive", what));
  if (std::adjacent_find(s.speeds.begin(), s.speeds.end()) != s.speeds.end())
    throw InputError(fmt::format("Hugoniot sweep: one of the {} is given twice", what));
  HugoniotSweep sweep;
  const auto stage = sweep_stage(s.case_file, s.method);
  sweep.stage = stage.first;
  fs::create_directories(s.folder);
  for (double value : s.speeds)
    sweep.points.push_back(run_one(s, value, s.folder / value_folder(s.method, value), stage));

  const char* first = s.method == "nphug" ? "target_pressure_GPa" : s.method == "msst" ? "shock_speed_set_km_s"
                                                                                        : "piston_speed_km_s";
  io::CsvWriter csv(s.folder / "hugoniot_sweep.csv",
                    {first, "up_km_s", "us_km_s", "us_stderr_km_s", "front_residual_rms_A",
                     "pressure_GPa", "pressure_rankine_hugoniot_GPa", "density_g_cc", "temperature_K"});
  std::vector<double> up, us;
  for (const SweepPoint& p : sweep.points) {
    csv.row({p.piston, p.up, p.us, p.us_stderr, p.front_rms, p.pressure, p.pressure_rh, p.density, p.temperature});
    up.push_back(p.up);
    us.push_back(p.us);
  }
  if (sweep.points.size() < 2) return sweep;
  sweep.fit = analysis::fit_us_up(up, us);
  write_file_atomically(s.folder / "hugoniot_fit.toml",
                        analysis::us_up_fit_toml(*sweep.fit) +
                            fmt::format("\n[experiment_copper]  # Marsh, LASL Shock Hugoniot Data (1980); Mitchell & "
                                        "Nellis, J. Appl. Phys. 52, 3363 (1981)\nc0_km_s = {}\ns = {}\n",
                                        kCopperC0, kCopperS));
  return sweep;
}

}  // namespace shockfield::md
