// `shockfield bridge spall RUN`: the spall strength of an MD tension run (a [[stage]] with
// deform_rate ≥ 0: uniaxial strain, as behind a release in a plate, or triaxial expansion) →
// [spall] strength and strain_rate of a material file, the instantaneous spall criterion MPM
// reads (materials/spall.hpp: failure once the mean stress tr σ/3 = −P falls below −σ_spall;
// Antoun et al. 2003 §1.3). σ_spall = the largest tensile mean stress −P of the thermo table before
// void nucleation, detected as the abrupt drop of the tension that follows it
// (bridge_md_strength.hpp), at the volumetric strain rate (1/V) dV/dt measured over the same rows.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "shockfield/app/bridge_md_strength.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;

struct SpallOptions {
  fs::path run;
  std::string stage;
  PeakOptions peak;
  BridgeOutput out;
};

constexpr const char* kWhat =
    "an MD tension run: a [[stage]] with deform_rate >= 0 in every direction (uniaxial strain, e.g. [0, 0, 0.01] "
    "1/ps, or triaxial expansion), run past void nucleation";

void run(const SpallOptions& o, const std::vector<std::string>& command_line) {
  const DeformRun r = read_deform_run(o.run, o.stage, static_cast<std::size_t>(o.peak.fit_rows) + 2, "bridge spall", kWhat);
  const fs::path resolved = r.folder / "config.resolved.toml";
  if (r.rate[0] < 0 || r.rate[1] < 0 || r.rate[2] < 0 || r.rate[0] + r.rate[1] + r.rate[2] <= 0)
    throw InputError(fmt::format("{}: stage '{}' has deform_rate [{:.6g}, {:.6g}, {:.6g}] 1/ps: bridge spall reads {}",
                                 resolved.string(), r.stage, r.rate[0] * 1e-12, r.rate[1] * 1e-12, r.rate[2] * 1e-12,
                                 kWhat));
  std::vector<double> tension(r.press.size());
  for (std::size_t i = 0; i < tension.size(); ++i) tension[i] = -r.press[i];
  const Peak peak = peak_before_drop(r.time, tension, o.peak, "the tensile mean stress -press_bar", "void nucleation",
                                     r.thermo_file.string());
  const double rate = log_rate(r.time, r.volume, peak.first_fit_row, peak.row);  // (1/V) dV/dt
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw InputError(fmt::format("{}: the volume (volume_A3) does not grow over the rows before the peak (rate {:.3g} "
                                 "1/s): not a tension run", r.thermo_file.string(), rate));
  const double vol_strain = std::log(r.volume[peak.row] / r.volume.front());
  int axis = -1;  // the one stretched axis of a uniaxial-strain run
  for (int k = 0; k < 3; ++k)
    if (r.rate[static_cast<std::size_t>(k)] > 0) axis = axis == -1 ? k : 3;
  const std::string rate_note = fmt::format("{:.3g}", rate);
  std::map<std::string, double> values{{"spall.strength", peak.value}, {"spall.strain_rate", rate}};
  const std::string note = fmt::format(
      "MD spall strength of {} (stage '{}'): the largest tensile mean stress before void nucleation, at the "
      "volumetric strain rate {} 1/s; perfect crystal at MD rates: an upper bound for a plate at ~1e6 1/s (no "
      "pre-existing voids, inclusions or grain boundaries)",
      r.folder.filename().string(), r.stage, rate_note);
  toml::table entry = materials::bridge_provenance_entry(command_line);
  entry.insert("inputs", toml::array{deform_run_input(r)});
  toml::table fit{{"measure", "largest tensile mean stress -P (thermo press_bar) before its abrupt drop"},
                  {"strain_rate_1_s", rate},
                  {"strain_rate_measure", "volumetric (1/V) dV/dt, least squares of ln V over the fitted rows"},
                  {"volumetric_strain_at_peak", vol_strain},
                  {"initial_pressure_Pa", r.press.front()}};
  insert_peak(fit, "strength", peak, o.peak);
  if (axis >= 0 && axis < 3) {
    const auto a = static_cast<std::size_t>(axis);
    fit.insert("axis", std::string(1, "xyz"[a]));
    const auto axial = value_at_peak(r.time, [&] {
      std::vector<double> v(r.p[a].size());
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = -r.p[a][i];
      return v;
    }(), peak);
    fit.insert("axial_tension_at_break_Pa", axial[0]);
    fit.insert("axial_tension_at_break_stderr_Pa", axial[1]);
  }
  entry.insert("fit", fit);
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "spall", values, {{"spall.note", note}},
                                    entry);
  std::printf("%s (stage '%s', %zu rows)\n  spall strength = %.4f +- %.4f GPa (tensile mean stress at t = %.3f ps; "
              "fit %.3g, sampling %.3g GPa)\n  strain rate    = %.4g 1/s (volumetric), volumetric strain %.4f\n"
              "  nucleation: tension falls to %.0f%% within %.3g ps\n-> %s\n",
              r.folder.string().c_str(), r.stage.c_str(), r.time.size(), peak.value * 1e-9, peak.stderr * 1e-9,
              peak.time * 1e12, peak.fit_stderr * 1e-9, peak.sampling * 1e-9, rate, vol_strain,
              100.0 * (1.0 - o.peak.drop), peak.drop_time * 1e12, o.out.file.string().c_str());
}

}  // namespace

void add_bridge_spall_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<SpallOptions>();
  CLI::App* cmd = bridge.add_subcommand(
      "spall",
      "MD tension run -> spall strength. Reads an MD run folder with a [[stage]] deform_rate >= 0\n"
      "(uniaxial strain or triaxial expansion past void nucleation) and its thermo.csv: the spall\n"
      "strength is the largest tensile mean stress -P before the abrupt drop that marks void\n"
      "nucleation (below (1 - drop) of the maximum, faster than max-drop-ratio times the rise), from a\n"
      "quadratic fit of the last rows before it, with its standard error (fit + sampling); the\n"
      "strain rate is the measured volumetric rate (1/V) dV/dt there. Writes [spall] strength and\n"
      "strain_rate (MPM's criterion: failure when the mean stress falls below -strength) and\n"
      "[provenance.spall]. MD rates (1e9-1e10 /s) and perfect crystals give upper bounds.\n"
      "Example: shockfield bridge spall runs/cu_tension -o cu_md.toml --update");
  cmd->add_option("run", o->run, "MD run folder with a tension (deform_rate) stage")->required();
  cmd->add_option("--stage", o->stage, "The deform stage to read, when the run has several");
  add_peak_options(*cmd, o->peak, "void nucleation");
  add_bridge_output_options(*cmd, o->out, "[spall]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
