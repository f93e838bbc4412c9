#include "shockfield/app/bridge_md_strength.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/sha256.hpp"

namespace shockfield::app {

namespace fs = std::filesystem;

std::vector<std::vector<double>> read_columns(const fs::path& file, const std::vector<std::string>& wanted,
                                              const std::string& expected) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot read (expected {})", file.string(), expected));
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream ss(line); std::getline(ss, cell, ',');) names.push_back(cell);
  std::vector<std::size_t> index;
  for (const std::string& w : wanted) {
    const auto it = std::find(names.begin(), names.end(), w);
    if (it == names.end())
      throw InputError(fmt::format("{}: no column '{}' (expected {})", file.string(), w, expected));
    index.push_back(static_cast<std::size_t>(it - names.begin()));
  }
  std::vector<std::vector<double>> cols(wanted.size());
  for (std::size_t row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    for (std::stringstream ss(line); std::getline(ss, cell, ',');) cells.push_back(cell);
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      char* end = nullptr;
      const double v = index[k] < cells.size() ? std::strtod(cells[index[k]].c_str(), &end) : NAN;
      if (index[k] >= cells.size() || end == cells[index[k]].c_str() || !std::isfinite(v))
        throw InputError(fmt::format("{}: line {}: column '{}' is not a finite number", file.string(), row, wanted[k]));
      cols[k].push_back(v);
    }
  }
  return cols;
}

namespace {

constexpr double kBarToPa = 1e5, kPsToS = 1e-12, kAToM = 1e-10;

// Quadratic least squares y = a + b·x + c·x² (x = t − t*, in the rows' own time unit) with
// C = σ²(XᵀX)⁻¹, σ² = χ²/(n − 3).
struct Quadratic {
  Eigen::Vector3d coef;
  Eigen::Matrix3d cov;
  double sigma = 0;
  double at(double x) const { return coef(0) + x * (coef(1) + x * coef(2)); }
  double var_at(double x) const {
    const Eigen::Vector3d g(1.0, x, x * x);
    return g.dot(cov * g);
  }
};
Quadratic fit_quadratic(const std::vector<double>& t, const std::vector<double>& y, std::size_t first,
                        std::size_t last, double t0, double scale) {
  const auto n = static_cast<Eigen::Index>(last - first + 1);
  Eigen::MatrixXd x(n, 3);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double s = (t[first + static_cast<std::size_t>(i)] - t0) / scale;
    x.row(i) << 1.0, s, s * s;
    v(i) = y[first + static_cast<std::size_t>(i)];
  }
  const Eigen::Matrix3d normal = x.transpose() * x;
  Quadratic q;
  q.coef = normal.ldlt().solve(x.transpose() * v);
  const double chi2 = (v - x * q.coef).squaredNorm();
  q.sigma = std::sqrt(chi2 / static_cast<double>(n - 3));
  q.cov = q.sigma * q.sigma * normal.inverse();
  return q;
}

// The value of the fit at the break (Peak's rule), in the fit's scaled time: {value, variance,
// Δ, time}.
std::array<double, 4> break_value(const Quadratic& q, double x_first, double x_next, bool& vertex) {
  const double a = q.coef(0), b = q.coef(1), c = q.coef(2);
  vertex = false;
  if (c < 0.0) {
    const double xv = -b / (2.0 * c);
    if (xv >= x_first && xv <= 0.0) {  // the fitted maximum lies inside the fitted rows
      vertex = true;
      const Eigen::Vector3d g(1.0, -b / (2.0 * c), b * b / (4.0 * c * c));  // ∂(a − b²/4c)/∂(a, b, c)
      return {a - b * b / (4.0 * c), g.dot(q.cov * g), 0.0, xv};
    }
  }
  // Rising at the last row before the drop: the break lies in (t*, t_{i*+1}], where the fit rises
  // at most to its value at min(vertex, t_{i*+1}).
  const double x_top = c < 0.0 ? std::clamp(-b / (2.0 * c), 0.0, x_next) : x_next;
  const double delta = std::max(0.0, q.at(x_top) - a);
  return {a + 0.5 * delta, q.cov(0, 0), delta, 0.5 * x_top};
}

}  // namespace

DeformRun read_deform_run(const fs::path& folder, const std::string& stage, std::size_t min_rows,
                          const std::string& command, const std::string& what) {
  DeformRun r;
  r.folder = fs::absolute(folder).lexically_normal();
  const fs::path resolved = folder / "config.resolved.toml";
  if (!fs::is_directory(folder) || !fs::exists(resolved))
    throw InputError(fmt::format("{}: not a run folder (no config.resolved.toml); {} reads {}", folder.string(),
                                 command, what));
  toml::table cfg;
  try {
    cfg = toml::parse_file(resolved.string());
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}: not a TOML file ({})", resolved.string(), e.description()));
  }
  const std::string method = cfg["method"].value_or(std::string{});
  if (method != "md")
    throw InputError(fmt::format("{}: method = \"{}\": {} reads {} (method = \"md\")", resolved.string(), method,
                                 command, what));
  const toml::array* stages = cfg["stage"].as_array();
  long long start = 0, steps = 0;
  std::vector<std::string> found;
  bool picked = false;
  for (std::size_t i = 0; stages && i < stages->size(); ++i) {
    const toml::table* s = stages->get(i)->as_table();
    if (!s) continue;
    // The ranges the MD case reader accepts (docs/md.md): steps >= 0, deform_rate in [-10, 10] 1/ps.
    const long long n = (*s)["steps"].value_or(-1LL);
    if (n < 0 || n > 1'000'000'000'000LL)
      throw InputError(fmt::format("{}: key 'stage[{}].steps': expected an integer in [0, 1e12]", resolved.string(), i));
    const std::string name = (*s)["name"].value_or(fmt::format("stage {}", i + 1));
    const toml::node* rate_node = s->get("deform_rate");
    const toml::array* rate = rate_node ? rate_node->as_array() : nullptr;
    if (rate_node) {
      std::array<double, 3> v{NAN, NAN, NAN};
      for (std::size_t k = 0; rate && rate->size() == 3 && k < 3; ++k) v[k] = rate->get(k)->value_or(NAN);
      if (!(std::abs(v[0]) <= 10 && std::abs(v[1]) <= 10 && std::abs(v[2]) <= 10))
        throw InputError(fmt::format("{}: key 'stage[{}].deform_rate': expected three numbers in [-10, 10] 1/ps",
                                     resolved.string(), i));
      found.push_back(name);
      if (!picked && (stage.empty() || stage == name)) {
        picked = true;
        r.stage = name;
        for (std::size_t k = 0; k < 3; ++k) r.rate[k] = v[k] / kPsToS;
        steps = n;
      }
    }
    if (!picked) start += n;
  }
  if (found.empty())
    throw InputError(fmt::format("{}: no [[stage]] with deform_rate: {} reads {}; a flyer-plate or piston run "
                                 "(shock loading, profiles.csv) is not read by it", resolved.string(), command, what));
  if (!picked)
    throw InputError(fmt::format("{}: no deform stage named '{}' (deform stages: {})", resolved.string(), stage,
                                 fmt::join(found, ", ")));
  if (stage.empty() && found.size() > 1)
    throw InputError(fmt::format("{}: {} deform stages ({}): choose one with --stage", resolved.string(),
                                 found.size(), fmt::join(found, ", ")));
  if (const toml::table* lat = cfg.at_path("system.lattice").as_table())
    for (std::size_t k = 0; k < 3; ++k)
      if (const toml::node* node = lat->get(std::string("orient_") + "xyz"[k])) {
        const toml::array* o = node->as_array();
        std::array<long long, 3> v{0, 0, 0};
        for (std::size_t j = 0; o && o->size() == 3 && j < 3; ++j) v[j] = o->get(j)->value_or(0LL);
        if (std::abs(v[0]) > 1000 || std::abs(v[1]) > 1000 || std::abs(v[2]) > 1000 || v == std::array<long long, 3>{})
          throw InputError(fmt::format("{}: key 'system.lattice.orient_{}': expected three integers, not all 0, "
                                       "within +-1000", resolved.string(), "xyz"[k]));
        for (std::size_t j = 0; j < 3; ++j) r.orient[k][j] = static_cast<int>(v[j]);
      }
  r.config_sha256 = sha256_file_hex(resolved);
  r.thermo_file = r.folder / "thermo.csv";
  if (!fs::exists(r.thermo_file))
    throw InputError(fmt::format("{}: no thermo.csv in the run folder ({} reads the stress of the thermo table)",
                                 folder.string(), command));
  const auto cols = read_columns(r.thermo_file, {"step", "time_ps", "press_bar", "pxx_bar", "pyy_bar", "pzz_bar",
                                                 "pxy_bar", "pxz_bar", "pyz_bar", "volume_A3", "lx_A", "ly_A", "lz_A"},
                                 "the thermo.csv of an MD run: step, time_ps, press_bar, pxx_bar, ..., volume_A3, lx_A, ly_A, lz_A");
  // Bounds no MD run reaches, so that the fits' sums stay finite: |p| <= 1e9 bar (1e5 GPa),
  // 0 < volume <= 1e18 Å³, 0 < lengths <= 1e6 Å, |t| <= 1e9 ps.
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    const auto check = [&](std::size_t k, double lo, double hi, const char* name) {
      if (!(cols[k][i] > lo && cols[k][i] <= hi))
        throw InputError(fmt::format("{}: data row {}: {} = {} outside ({}, {}]", r.thermo_file.string(), i + 1, name,
                                     cols[k][i], lo, hi));
    };
    check(1, -1e9, 1e9, "time_ps");
    for (std::size_t k = 2; k < 9; ++k) check(k, -1e9, 1e9, "a pressure column (bar)");
    check(9, 0.0, 1e18, "volume_A3");
    for (std::size_t k = 10; k < 13; ++k) check(k, 0.0, 1e6, "a box length (A)");
  }
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    const double step = cols[0][i];
    if (step < static_cast<double>(start) || step > static_cast<double>(start + steps)) continue;
    if (!r.time.empty() && cols[1][i] * kPsToS <= r.time.back()) continue;  // a resumed run repeats rows
    r.time.push_back(cols[1][i] * kPsToS);
    r.press.push_back(cols[2][i] * kBarToPa);
    for (std::size_t k = 0; k < 6; ++k) r.p[k].push_back(cols[3 + k][i] * kBarToPa);
    r.volume.push_back(cols[9][i] * kAToM * kAToM * kAToM);
    for (std::size_t k = 0; k < 3; ++k) r.length[k].push_back(cols[10 + k][i] * kAToM);
  }
  if (r.time.size() < min_rows)
    throw InputError(fmt::format("{}: {} thermo rows in stage '{}' (steps {} to {} in {}), expected at least {}: "
                                 "write thermo more often ([output] thermo_every) or run the stage longer",
                                 r.thermo_file.string(), r.time.size(), r.stage, start, start + steps,
                                 resolved.string(), min_rows));
  r.thermo_sha256 = sha256_file_hex(r.thermo_file);
  return r;
}

Peak peak_before_drop(const std::vector<double>& t, const std::vector<double>& y, const PeakOptions& o,
                      const std::string& series, const std::string& event, const std::string& source) {
  Peak p;
  p.row = static_cast<std::size_t>(std::max_element(y.begin(), y.end()) - y.begin());
  const double top = y[p.row];
  if (!(top > 0.0))
    throw InputError(fmt::format("{}: {} is never positive (largest {:.4g} GPa): no {} to measure", source, series,
                                 top * 1e-9, event));
  const auto ufit = static_cast<std::size_t>(o.fit_rows);
  if (p.row + 1 < ufit)
    throw InputError(fmt::format("{}: the maximum of {} ({:.4g} GPa) is at row {} of the stage, expected at least "
                                 "{} rows before it for the fit (thermo_every smaller)", source, series, top * 1e-9,
                                 p.row + 1, ufit));
  p.drop_row = p.row + 1;
  while (p.drop_row < y.size() && y[p.drop_row] > (1.0 - o.drop) * top) ++p.drop_row;
  if (p.drop_row == y.size())
    throw InputError(fmt::format("{}: no {} found: {} reaches {:.4g} GPa at t = {:.4g} ps{} and does not fall below "
                                 "{:.0f}% of it afterwards; run the stage longer (more strain)", source, event,
                                 series, top * 1e-9, t[p.row] * 1e12, p.row + 1 == y.size() ? " (the last row)" : "",
                                 100.0 * (1.0 - o.drop)));
  p.drop_time = t[p.drop_row] - t[p.row];
  // The rise over the same fraction: from the last row below (1 − drop)·peak before the maximum.
  std::size_t rise_row = p.row;
  while (rise_row > 0 && y[rise_row - 1] > (1.0 - o.drop) * top) --rise_row;
  p.rise_time = t[p.row] - t[rise_row > 0 ? rise_row - 1 : 0];
  if (!(p.drop_time < o.max_drop_ratio * p.rise_time))
    throw InputError(fmt::format("{}: no {} found: {} has a maximum of {:.4g} GPa at t = {:.4g} ps but falls to "
                                 "{:.0f}% of it over {:.3g} ps after rising from there over {:.3g} ps (ratio {:.2f}, "
                                 "expected an abrupt drop, ratio < {:.2f}): a smooth maximum (e.g. elastic softening), "
                                 "not a break",
                                 source, event, series, top * 1e-9, t[p.row] * 1e12, 100.0 * (1.0 - o.drop),
                                 p.drop_time * 1e12, p.rise_time * 1e12, p.drop_time / p.rise_time, o.max_drop_ratio));
  p.first_fit_row = p.row + 1 - ufit;
  const auto v = value_at_peak(t, y, p);
  const double scale = t[p.row] - t[p.first_fit_row];
  const Quadratic q = fit_quadratic(t, y, p.first_fit_row, p.row, t[p.row], scale);
  bool vertex = false;
  const auto b = break_value(q, -1.0, (t[p.row + 1] - t[p.row]) / scale, vertex);
  p.value = v[0];
  p.stderr = v[1];
  p.fit_stderr = std::sqrt(b[1]);
  p.sampling = b[2] / std::sqrt(12.0);
  p.noise = q.sigma;
  p.time = t[p.row] + b[3] * scale;
  p.vertex = vertex;
  return p;
}

std::array<double, 2> value_at_peak(const std::vector<double>& t, const std::vector<double>& y, const Peak& peak) {
  const double scale = t[peak.row] - t[peak.first_fit_row];
  const Quadratic q = fit_quadratic(t, y, peak.first_fit_row, peak.row, t[peak.row], scale);
  bool vertex = false;
  const auto b = break_value(q, -1.0, (t[peak.row + 1] - t[peak.row]) / scale, vertex);
  return {b[0], std::sqrt(b[1] + b[2] * b[2] / 12.0)};
}

double log_rate(const std::vector<double>& t, const std::vector<double>& x, std::size_t first, std::size_t last) {
  double st = 0, sl = 0, stt = 0, stl = 0;
  const double n = static_cast<double>(last - first + 1);
  for (std::size_t i = first; i <= last; ++i) {
    const double tt = t[i] - t[first], l = std::log(x[i]);
    st += tt, sl += l, stt += tt * tt, stl += tt * l;
  }
  return (n * stl - st * sl) / (n * stt - st * st);
}

toml::table deform_run_input(const DeformRun& run) {
  return toml::table{{"folder", run.folder.string()},
                     {"config_sha256", run.config_sha256},
                     {"thermo", run.thermo_file.filename().string()},
                     {"thermo_sha256", run.thermo_sha256},
                     {"stage", run.stage},
                     {"deform_rate_1_s", toml::array{run.rate[0], run.rate[1], run.rate[2]}}};
}

void insert_peak(toml::table& fit, const std::string& prefix, const Peak& peak, const PeakOptions& o) {
  fit.insert(prefix + "_Pa", peak.value);
  fit.insert(prefix + "_stderr_Pa", peak.stderr);
  fit.insert(prefix + "_fit_stderr_Pa", peak.fit_stderr);
  fit.insert(prefix + "_sampling_stderr_Pa", peak.sampling);
  fit.insert(prefix + "_noise_rms_Pa", peak.noise);
  fit.insert(prefix + "_break_time_ps", peak.time * 1e12);
  fit.insert(prefix + "_drop_time_ps", peak.drop_time * 1e12);
  fit.insert(prefix + "_rise_time_ps", peak.rise_time * 1e12);
  fit.insert(prefix + "_peak_at", peak.vertex ? "vertex of the fit (a rounded maximum)"
                                              : "cusp: rising until the drop; midpoint of the last interval");
  fit.insert("fit_rows", static_cast<int64_t>(o.fit_rows));
  fit.insert("drop_fraction", o.drop);
  fit.insert("max_drop_ratio", o.max_drop_ratio);
}

void add_peak_options(CLI::App& cmd, PeakOptions& o, const std::string& event) {
  cmd.add_option("--fit-rows", o.fit_rows, "Thermo rows of the quadratic fit ending at the maximum")
      ->check(CLI::Range(4, 100000))
      ->capture_default_str();
  cmd.add_option("--drop", o.drop, "The " + event + " is the stress falling below (1 - drop) of its maximum")
      ->check(CLI::Range(0.01, 0.99))
      ->capture_default_str();
  cmd.add_option("--max-drop-ratio", o.max_drop_ratio,
                 "... in less than this fraction of the time it took to rise from (1 - drop) of the maximum to the "
                 "maximum; a slower fall is a smooth maximum, refused")
      ->check(CLI::Range(1e-6, 10.0))
      ->capture_default_str();
}

}  // namespace shockfield::app
