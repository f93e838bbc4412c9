// `shockfield bridge yield RUN`: the Hugoniot elastic limit of a single crystal from an MD
// uniaxial-strain compression run (a [[stage]] with one deform_rate component < 0) → a J2 yield
// stress for MPM and the initial slip resistance g0 of the crystal law of PD (Liu et al. 2025,
// eqs. 38–41). The elastic–plastic break is the abrupt drop of the stress difference
// D = σ_L − σ_T (σ_L the longitudinal, σ_T the mean lateral compressive stress) when dislocations
// nucleate (bridge_md_strength.hpp). At the break:
//   σ_HEL = Δσ_L (the rise of σ_L from the stage start: the initial thermal pressure is no strength);
//   ν from the same elastic rise, ν/(1 − ν) = Δσ_T/Δσ_L (uniaxial strain of an isotropic solid), or --poisson;
//   Y = σ_HEL (1 − 2ν)/(1 − ν)  (von Mises in uniaxial strain: Y = σ_L − σ_T; Meyers (1994), elastoplastic shock waves);
//   g0 = τ_RSS = m·D with the Schmid factor m = max over fcc {111}<110> of |(d·n)(d·b)| of the
//        loading direction d (exact when σ_T is the same on both lateral axes, as along [100], [111]).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "shockfield/app/bridge_md_strength.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;

struct YieldOptions {
  fs::path run;
  std::string stage;
  std::optional<double> poisson;
  PeakOptions peak;
  BridgeOutput out;
};

constexpr const char* kWhat =
    "an MD uniaxial-strain compression run of a single crystal: a [[stage]] with one deform_rate component < 0 and "
    "the others 0 (e.g. [0, 0, -0.01] 1/ps), run past the elastic-plastic break";

// The 12 fcc slip systems {111}<110>, unnormalized.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> fcc_slip_systems() {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> s;
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, 1, 1), Eigen::Vector3d(1, -1, 1),
                                  Eigen::Vector3d(1, 1, -1)})
    for (const Eigen::Vector3d& b : {Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(1, 0, -1), Eigen::Vector3d(0, 1, -1),
                                    Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)})
      if (n.dot(b) == 0.0) s.emplace_back(n.normalized(), b.normalized());
  return s;
}

// The straight line through the first `k` rows of (t, v) at t.front(): {value, standard error}
// (k < 3: the first row, its error unknown, 0).
std::array<double, 2> intercept(const std::vector<double>& t, const std::vector<double>& v, std::size_t k) {
  if (k < 3) return {v.front(), 0.0};
  double st = 0, sv = 0, stt = 0, stv = 0;
  const double n = static_cast<double>(k);
  for (std::size_t i = 0; i < k; ++i) {
    const double x = t[i] - t.front();
    st += x, sv += v[i], stt += x * x, stv += x * v[i];
  }
  const double det = n * stt - st * st, slope = (n * stv - st * sv) / det, a = (sv - slope * st) / n;
  double chi2 = 0;
  for (std::size_t i = 0; i < k; ++i) chi2 += std::pow(v[i] - a - slope * (t[i] - t.front()), 2);
  return {a, std::sqrt(chi2 / (n - 2.0) * stt / det)};
}

// Schmid factor of a loading direction (crystal frame): the largest |cos φ cos λ| over the slip systems.
double fcc_schmid_factor(const Eigen::Vector3d& direction) {
  const Eigen::Vector3d d = direction.normalized();
  double m = 0.0;
  for (const auto& [n, b] : fcc_slip_systems()) m = std::max(m, std::abs(d.dot(n) * d.dot(b)));
  return m;
}

void run(const YieldOptions& o, const std::vector<std::string>& command_line) {
  const DeformRun r = read_deform_run(o.run, o.stage, static_cast<std::size_t>(o.peak.fit_rows) + 2, "bridge yield", kWhat);
  const fs::path resolved = r.folder / "config.resolved.toml";
  int axis = -1, nonzero = 0;
  for (int k = 0; k < 3; ++k)
    if (r.rate[static_cast<std::size_t>(k)] != 0.0) ++nonzero, axis = k;
  if (nonzero != 1 || r.rate[static_cast<std::size_t>(axis)] > 0)
    throw InputError(fmt::format("{}: stage '{}' has deform_rate [{:.6g}, {:.6g}, {:.6g}] 1/ps: bridge yield reads {}",
                                 resolved.string(), r.stage, r.rate[0] * 1e-12, r.rate[1] * 1e-12, r.rate[2] * 1e-12,
                                 kWhat));
  const auto a = static_cast<std::size_t>(axis), b = (a + 1) % 3, c = (a + 2) % 3;
  const std::size_t n = r.time.size();
  std::vector<double> sl(n), st(n), d(n);
  for (std::size_t i = 0; i < n; ++i) {
    sl[i] = r.p[a][i];
    st[i] = 0.5 * (r.p[b][i] + r.p[c][i]);
    d[i] = sl[i] - st[i];
  }
  const Peak peak = peak_before_drop(r.time, d, o.peak, "the stress difference sigma_L - sigma_T (p" +
                                     std::string(1, "xyz"[a]) + " minus the mean of the lateral p)",
                                     "elastic-plastic break", r.thermo_file.string());
  // The initial state: σ_L and σ_T at the stage start, the intercepts of straight lines through
  // the first rows of the ramp (up to 10, all before the fit window), with the intercept's standard error.
  const std::size_t k0 = std::min<std::size_t>(10, peak.first_fit_row + 1);
  const auto start = [&](const std::vector<double>& v) { return intercept(r.time, v, k0); };
  const auto [l0, l0_err] = start(sl);
  const double t0 = start(st)[0];
  const auto l_at = value_at_peak(r.time, sl, peak), t_at = value_at_peak(r.time, st, peak);
  const double hel = l_at[0] - l0, hel_err = std::hypot(l_at[1], l0_err);
  const double dl = hel, dt = t_at[0] - t0;
  const double nu_measured = dt / (dl + dt);
  const double nu = o.poisson ? *o.poisson : nu_measured;
  if (!(nu > -1.0 && nu < 0.5))
    throw InputError(fmt::format("{}: the lateral and longitudinal stress rises to the break ({:.4g}, {:.4g} GPa) give "
                                 "nu = {:.4g}, outside (-1, 0.5); give --poisson", r.thermo_file.string(), dt * 1e-9,
                                 dl * 1e-9, nu_measured));
  const double factor = (1.0 - 2.0 * nu) / (1.0 - nu);
  const double y = hel * factor;
  const double y_err = o.poisson ? hel_err * factor : peak.stderr;  // with ν measured, Y = Δσ_L − Δσ_T = D − D0
  // The loading direction in the crystal: the lattice direction along the compressed box axis.
  const Eigen::Vector3d dir(r.orient[a][0], r.orient[a][1], r.orient[a][2]);
  const double m = fcc_schmid_factor(dir);
  const double g0 = m * peak.value, g0_err = m * peak.stderr;
  // Check: the largest resolved shear stress of the full measured tensor at the last row before the drop.
  Eigen::Matrix3d rot, p;
  for (int i = 0; i < 3; ++i)
    rot.row(i) = Eigen::Vector3d(r.orient[static_cast<std::size_t>(i)][0], r.orient[static_cast<std::size_t>(i)][1],
                                 r.orient[static_cast<std::size_t>(i)][2]).normalized();
  const std::size_t i = peak.row;
  p << r.p[0][i], r.p[3][i], r.p[4][i], r.p[3][i], r.p[1][i], r.p[5][i], r.p[4][i], r.p[5][i], r.p[2][i];
  const Eigen::Matrix3d pc = rot.transpose() * p * rot;
  double rss = 0.0;
  for (const auto& [sn, sb] : fcc_slip_systems()) rss = std::max(rss, std::abs(sn.dot(pc * sb)));
  const double rate = std::abs(log_rate(r.time, r.length[a], peak.first_fit_row, peak.row));
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw InputError(fmt::format("{}: the box length l{}_A does not change over the rows before the break: not a "
                                 "compression run", r.thermo_file.string(), "xyz"[a]));
  const std::string direction = fmt::format("[{}{}{}]", r.orient[a][0], r.orient[a][1], r.orient[a][2]);

  const std::map<std::string, double> values{
      {"strength.yield_stress", y}, {"strength.g0", g0}, {"strength.strain_rate", rate}};
  const std::string note = fmt::format(
      "MD yield of a perfect single crystal compressed along {} at {:.3g} 1/s (run {}): homogeneous dislocation "
      "nucleation in a defect-free crystal at MD strain rates, 1e3-1e4 times a plate impact's; yield_stress and g0 "
      "are upper bounds, one to two orders of magnitude above the strength of real, dislocated metal",
      direction, rate, r.folder.filename().string());
  toml::table entry = materials::bridge_provenance_entry(command_line);
  entry.insert("inputs", toml::array{deform_run_input(r)});
  toml::table fit{{"measure", "abrupt drop of the stress difference sigma_L - sigma_T (compressive-positive p)"},
                  {"axis", std::string(1, "xyz"[a])},
                  {"direction", direction},
                  {"schmid_factor", m},
                  {"hel_Pa", hel},
                  {"hel_stderr_Pa", hel_err},
                  {"sigma_l_at_break_Pa", l_at[0]},
                  {"sigma_t_at_break_Pa", t_at[0]},
                  {"sigma_l_initial_Pa", l0},
                  {"poisson", nu},
                  {"poisson_source", o.poisson ? "--poisson" : "measured: nu/(1-nu) = (rise of sigma_T)/(rise of sigma_L)"},
                  {"poisson_measured", nu_measured},
                  {"yield_stress_Pa", y},
                  {"yield_stress_stderr_Pa", y_err},
                  {"g0_Pa", g0},
                  {"g0_stderr_Pa", g0_err},
                  {"rss_full_tensor_last_row_Pa", rss},
                  {"lateral_difference_last_row_Pa", std::abs(r.p[b][i] - r.p[c][i])},
                  {"strain_rate_1_s", rate},
                  {"strain_rate_measure", "axial |d ln L/dt|, least squares over the fitted rows"}};
  insert_peak(fit, "stress_difference", peak, o.peak);
  entry.insert("fit", fit);
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "yield", values, {{"strength.note", note}},
                                    entry);
  std::printf("%s (stage '%s', %zu rows), loading along %s (Schmid factor %.4f)\n"
              "  HEL            = %.4f +- %.4f GPa (rise of sigma_L to the break at t = %.3f ps)\n"
              "  sigma_L - sigma_T at the break = %.4f +- %.4f GPa\n"
              "  poisson        = %.4f (%s)\n  yield_stress Y = %.4f +- %.4f GPa (J2, MPM)\n"
              "  g0 = tau_RSS   = %.4f +- %.4f GPa (PD crystal law; full-tensor check %.4f GPa)\n"
              "  strain rate    = %.4g 1/s\n-> %s\n",
              r.folder.string().c_str(), r.stage.c_str(), n, direction.c_str(), m, hel * 1e-9, hel_err * 1e-9,
              peak.time * 1e12, peak.value * 1e-9, peak.stderr * 1e-9, nu, o.poisson ? "given" : "measured",
              y * 1e-9, y_err * 1e-9, g0 * 1e-9, g0_err * 1e-9, rss * 1e-9, rate, o.out.file.string().c_str());
}

}  // namespace

void add_bridge_yield_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<YieldOptions>();
  CLI::App* cmd = bridge.add_subcommand(
      "yield",
      "MD uniaxial-strain compression of a single crystal -> J2 yield (MPM) and crystal g0 (PD).\n"
      "Reads an MD run folder with a [[stage]] deform_rate compressing one box axis and its\n"
      "thermo.csv: the elastic-plastic break is the abrupt drop of sigma_L - sigma_T (longitudinal\n"
      "minus mean lateral stress); the Hugoniot elastic limit HEL is the rise of sigma_L to it. Writes\n"
      "[strength] yield_stress = HEL (1 - 2 nu)/(1 - nu) (nu measured from the elastic rise, or\n"
      "--poisson), g0 = m (sigma_L - sigma_T), the resolved shear stress at yield with the fcc\n"
      "{111}<110> Schmid factor m of the loading direction (lattice orient), strain_rate, and the\n"
      "caveat of MD strain rates and perfect crystals in strength.note.\n"
      "Example: shockfield bridge yield runs/cu_111_compression -o cu_md.toml --update");
  cmd->add_option("run", o->run, "MD run folder with a uniaxial compression (deform_rate) stage")->required();
  cmd->add_option("--stage", o->stage, "The deform stage to read, when the run has several");
  cmd->add_option("--poisson", o->poisson, "Poisson's ratio for Y = HEL (1 - 2 nu)/(1 - nu) instead of the measured one")
      ->check(CLI::Range(-0.99, 0.49));
  add_peak_options(*cmd, o->peak, "elastic-plastic break");
  add_bridge_output_options(*cmd, o->out, "[strength]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
