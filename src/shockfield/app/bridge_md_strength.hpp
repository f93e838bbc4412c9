#pragma once
// What `bridge spall` and `bridge yield` read: an MD run folder with a strain-loading stage (a
// [[stage]] with deform_rate, md/fixes/deform.hpp: the box and the atoms stretched or compressed
// affinely at a constant engineering rate), its thermo.csv rows of that stage, and the one
// measurement both bridges make on them: the maximum of a stress series just before it drops
// abruptly (void nucleation for spall, dislocation nucleation for yield), with its uncertainty.
// docs/bridges.md §"bridge spall", §"bridge yield".
#include <CLI/CLI.hpp>
#include <toml++/toml.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::app {

/// The deform stage of an MD run folder and its thermo rows (SI: s, Pa, m³; pressures
/// compressive-positive as in thermo.csv).
struct DeformRun {
  std::filesystem::path folder, thermo_file;
  std::string config_sha256, thermo_sha256, stage;
  std::array<double, 3> rate{};  ///< nominal engineering strain rate per box axis, 1/s
  std::array<std::array<int, 3>, 3> orient{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  ///< lattice orient_x/y/z
  std::vector<double> time, volume;                                              ///< s, m³
  std::array<std::vector<double>, 3> length;                                     ///< box lengths, m
  std::array<std::vector<double>, 6> p;  ///< pxx, pyy, pzz, pxy, pxz, pyz, Pa
  std::vector<double> press;             ///< mean pressure, Pa
};

/// Reads `folder` for `command` ("bridge spall"): config.resolved.toml with method = "md" and a
/// stage with deform_rate (`stage` names it when there are several), and thermo.csv's rows of
/// that stage (at least `min_rows`). Every refusal is an InputError naming the folder or file and
/// what was expected; `what` says which run the bridge reads ("a uniaxial tension run ...").
DeformRun read_deform_run(const std::filesystem::path& folder, const std::string& stage, std::size_t min_rows,
                          const std::string& command, const std::string& what);

struct PeakOptions {
  int fit_rows = 8;             ///< rows of the local quadratic fit ending at the maximum
  double drop = 0.2;            ///< the series must fall below (1 − drop)·peak after the maximum
  double max_drop_ratio = 0.25; ///< ... in less than this fraction of the time it rose from (1 − drop)·peak
};

/// The maximum of `y` before an abrupt drop (docs/bridges.md): the row i* of the largest value,
/// a quadratic least-squares fit over the `fit_rows` rows ending at i*, and its maximum on
/// [t_first, t_{i*+1}] (the peak lies before the first row of the drop): the fit's vertex when it
/// falls inside the fitted rows, else f(t*) + Δ/2 with Δ the fit's further rise until t_{i*+1}
/// (the break is taken uniform in that interval). stderr² = the fit's variance of that value
/// (C = σ²(XᵀX)⁻¹, σ² = χ²/(n − 3); Press et al. (2007) §15.4) + Δ²/12.
struct Peak {
  std::size_t row = 0, drop_row = 0, first_fit_row = 0;
  double value = 0, stderr = 0, fit_stderr = 0, sampling = 0, noise = 0;
  double time = 0;       ///< s, the estimated time of the break (vertex, or t* + Δ-interval midpoint)
  double drop_time = 0;  ///< s, from the maximum to the first row below (1 − drop)·peak
  double rise_time = 0;  ///< s, from the last row below (1 − drop)·peak before the maximum to it
  bool vertex = false;   ///< true when the fitted maximum lies inside the fitted rows
};

/// `y` is the series (Pa), `t` its times (s, t.front() the stage start); `series` names it in
/// messages ("the tensile mean stress -press_bar"), `event` the break ("void nucleation"),
/// `source` the file. Refused (InputError): no positive value, the maximum at the last row or
/// with fewer than fit_rows rows before it, no drop below (1 − drop)·peak after it, a drop that
/// takes max_drop_ratio or more of the rise over the same fraction (a smooth maximum, e.g. the
/// elastic softening of [100] fcc under uniaxial strain, falls about as fast as it rose; a break
/// falls several times faster).
Peak peak_before_drop(const std::vector<double>& t, const std::vector<double>& y, const PeakOptions& o,
                      const std::string& series, const std::string& event, const std::string& source);

/// The same rule (vertex or cusp, from the rows of `peak`) applied to another series `y`, e.g. the
/// longitudinal stress at the break of the shear stress: {value, stderr}.
std::array<double, 2> value_at_peak(const std::vector<double>& t, const std::vector<double>& y, const Peak& peak);

/// d ln x / dt by least squares over rows [first, last] (1/s).
double log_rate(const std::vector<double>& t, const std::vector<double>& x, std::size_t first, std::size_t last);

/// --fit-rows, --drop, --max-drop-time; `event` names the break in the help ("void nucleation").
void add_peak_options(CLI::App& cmd, PeakOptions& o, const std::string& event);

/// The columns `wanted` of a CSV file with a header row, by name; InputError naming the file and
/// `expected` (what the file should be) for a missing column, and the line of a non-numeric cell.
std::vector<std::vector<double>> read_columns(const std::filesystem::path& file, const std::vector<std::string>& wanted,
                                              const std::string& expected);

/// The [provenance] input entry of a run: folder, config_sha256, thermo file and its SHA-256, stage.
toml::table deform_run_input(const DeformRun& run);

/// The peak's numbers for [provenance.<bridge>.fit], prefixed (e.g. "strength"): value, stderr,
/// fit_stderr, sampling, noise, time, drop_time, rows.
void insert_peak(toml::table& fit, const std::string& prefix, const Peak& peak, const PeakOptions& o);

}  // namespace shockfield::app
