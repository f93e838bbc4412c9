// `shockfield bridge domain-growth TRACKS`: the growth of a tracked hcp domain of an MD series
// (`analyze atoms --clusters ... --track`, tracks.csv) → the phase-field model of Xu et al. (2015)
// §4.4.3 ([phasefield] a, interface_width, relaxation_time of a material file). The measured
// radius R(t) is fitted to the sharp-interface law of the well-posed model,
// Ṙ = c₀ − (n − 1) D/R (phasefield/growth_fit.hpp; docs/theory/phasefield.md), and the model's
// parameters follow from c₀ = √(D/(2τ))(1 − 2a) and the front width W = √(2Dτ) the user chooses:
// τ = W²/(2D), a = (1 − c₀W/D)/2. A fit with D ≤ 0 (a domain that decelerates as it grows) is
// refused: no well-posed gradient flow has it. With --law paper the same radii are fitted to
// Xu et al. (2015)'s Ṙ = c₀ + (n − 1)D/R (their eq 43 with k = +2/R for an hcp sphere: the same
// fit, D of the other sign) and the sharp-front material ([phasefield] kind = "sharp_front",
// law, front_speed, curvature_coefficient) is written for D > 0. docs/bridges.md §"bridge domain-growth".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>

#include "shockfield/app/bridge_md_strength.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/phasefield/growth_fit.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;

constexpr double kA = 1e-10, kPs = 1e-12;

struct DomainGrowthOptions {
  fs::path tracks;
  double width = 0;  ///< Å; 0: not given
  std::string law = "allen_cahn";
  int track = 0;     ///< 0: the track with the most points
  double from = -INFINITY, until = INFINITY, time_scale = 1.0;
  std::string radius = "atomic";
  BridgeOutput out;
};

struct Series {
  int track = 0;
  std::vector<double> t, R;  ///< ps, Å
};

// The columns read of a tracks.csv: that of analyze atoms --track names its units (time_ps, or
// elapsed_timesteps without --timestep-size; L_A, atomic_volume_A3: docs/conventions.md), that of
// a phasefield run is in model units (time, L, atomic_volume).
std::vector<std::string> track_columns_of(const fs::path& file) {
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  const auto has = [&](const std::string& name) { return ("," + header + ",").find("," + name + ",") != std::string::npos; };
  if (!has("L_A")) return {"track", "time", "size", "L", "atomic_volume"};
  return {"track", has("elapsed_timesteps") ? "elapsed_timesteps" : "time_ps", "size", "L_A", "atomic_volume_A3"};
}

// The radius of each point of the chosen track in the time window.
Series read_track(const fs::path& file, const DomainGrowthOptions& o) {
  const auto cols = read_columns(file, track_columns_of(file),
                                 "the tracks.csv of shockfield analyze atoms --clusters ... --track (time_ps, L_A, "
                                 "atomic_volume_A3) or of a phasefield run (time, L, atomic_volume)");
  std::map<int, std::pair<std::size_t, double>> tracks;  // points and last size of each track
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    auto& [points, size] = tracks[static_cast<int>(cols[0][i])];
    ++points, size = cols[2][i];
  }
  Series s;
  s.track = o.track;
  if (s.track == 0) {
    std::pair<std::size_t, double> best{0, 0};
    for (const auto& [number, info] : tracks)
      if (info > best) best = info, s.track = number;
  }
  if (tracks.count(s.track) == 0)
    throw InputError(tracks.empty() ? fmt::format("{}: no tracked domain (no rows); are there hcp atoms in the frames "
                                                  "(--cluster-select acna:hcp)?", file.string())
                                    : fmt::format("{}: no track {} (--track)", file.string(), s.track));
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    const double t = cols[1][i] * o.time_scale;
    if (static_cast<int>(cols[0][i]) != s.track || t < o.from || t > o.until) continue;
    s.t.push_back(t);
    s.R.push_back(o.radius == "atomic" ? std::cbrt(3.0 * cols[4][i] / (4.0 * std::numbers::pi)) : cols[3][i]);
  }
  return s;
}

// The fit's numbers in SI units for [provenance.domain_growth.fit]; `sign` = −1 turns the fitted
// D of Ṙ = c₀ − 2D/R into that of Ṙ = c₀ + 2D/R (paper), with its covariance.
toml::table fit_table(const phasefield::GrowthFit& fit, double sign, const Series& s, const DomainGrowthOptions& o) {
  const double D = sign * fit.D;
  toml::table t{
      {"radius", o.radius == "atomic" ? "equivalent sphere of the atomic volume, (3 V_atomic/4 pi)^(1/3)"
                                      : "moment size L = (abc)^(1/3)"},
      {"c0_m_s", fit.c0 * kA / kPs}, {"c0_stderr_m_s", fit.c0_stderr * kA / kPs},
      {"D_m2_s", D * kA * kA / kPs}, {"D_stderr_m2_s", fit.D_stderr * kA * kA / kPs},
      {"c0_D_covariance_m3_s2", sign * fit.c0_D_covariance * kA * kA * kA / (kPs * kPs)},
      {"R0_m", fit.R0 * kA}, {"R0_stderr_m", fit.R0_stderr * kA}, {"residual_rms_m", fit.residual_rms * kA},
      {"first_time_s", s.t.front() * kPs}, {"last_time_s", s.t.back() * kPs},
      {"first_radius_m", s.R.front() * kA}, {"last_radius_m", s.R.back() * kA}, {"converged", fit.converged}};
  return t;
}

// --law paper: the sharp-front material of Ṙ = c₀ + 2D/R (D > 0), for [model] kind = "sharp_front".
void write_paper_law(const DomainGrowthOptions& o, const Series& s, const phasefield::GrowthFit& fit,
                     const fs::path& file, const std::string& what, toml::table entry) {
  const double c0 = fit.c0, D = -fit.D;
  if (!(D > 0.0))
    throw InputError(fmt::format(
        "{}: the fitted D = {:.4g} +- {:.2g} A^2/ps of the paper's law dR/dt = c0 + 2D/R is not positive (c0 = {:.4g} "
        "+- {:.2g} A/ps): the domain grows faster as it grows (R from {:.4g} to {:.4g} A), the sign of the well-posed "
        "law dR/dt = c0 - 2D/R, which --law allen_cahn (the default) fits. Nothing written",
        what, D, fit.D_stderr, c0, fit.c0_stderr, s.R.front(), s.R.back()));
  toml::table t = fit_table(fit, -1.0, s, o);
  t.insert("law", "dR/dt = c0 + (n-1) D/R, n = 3: Xu et al. (2015) eq 43 v = c0 + D k with k = +2/R for a convex hcp "
                  "sphere (ill-posed for other shapes; evolved for spheres only, [model] kind = sharp_front)");
  if (c0 < 0) t.insert("fixed_radius_m", -2 * D / c0 * kA);
  entry.insert("fit", t);
  const std::string note = fmt::format(
      "sharp-front law of the growth of track {} of {} (R from {:.4g} to {:.4g} A, t from {:.4g} to {:.4g} ps): "
      "dR/dt = c0 + 2D/R with c0 = {:.4g} A/ps, D = {:.4g} A^2/ps (Xu et al. (2015) eq 43 as printed)",
      s.track, file.filename().string(), s.R.front(), s.R.back(), s.t.front(), s.t.back(), c0, D);
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "domain_growth",
                                    {{"phasefield.front_speed", c0 * kA / kPs},
                                     {"phasefield.curvature_coefficient", D * kA * kA / kPs}},
                                    {{"phasefield.kind", "sharp_front"}, {"phasefield.law", "paper"},
                                     {"phasefield.note", note}},
                                    entry);
  std::printf("%s (%d points, t = %.4g ... %.4g ps, R = %.4g ... %.4g A)\n"
              "  dR/dt = c0 + 2D/R (paper):  c0 = %.4g +- %.2g A/ps,  D = %.4g +- %.2g A^2/ps  (R0 = %.4g +- %.2g A, "
              "rms %.3g A)\n-> %s\n",
              what.c_str(), fit.points, s.t.front(), s.t.back(), s.R.front(), s.R.back(), c0, fit.c0_stderr, D,
              fit.D_stderr, fit.R0, fit.R0_stderr, fit.residual_rms, o.out.file.string().c_str());
}

void run(const DomainGrowthOptions& o, const std::vector<std::string>& command_line) {
  if (o.law == "paper" && o.width > 0)
    throw InputError("--interface-width: the paper's law (--law paper) is a sharp front, it has no front width");
  if (o.law == "allen_cahn" && !(o.width > 0))
    throw InputError("--interface-width W is required with --law allen_cahn (the field model's front width)");
  const fs::path file = fs::is_directory(o.tracks) ? o.tracks / "tracks.csv" : o.tracks;
  if (!fs::exists(file))
    throw InputError(fmt::format("{}: no such file (expected the tracks.csv of shockfield analyze atoms --track, or its "
                                 "output folder)", file.string()));
  const Series s = read_track(file, o);
  const std::string what = fmt::format("{}: track {}", file.string(), s.track);
  const phasefield::GrowthFit fit = phasefield::fit_growth_law(s.t, s.R, 3, what);
  toml::table entry = materials::bridge_provenance_entry(command_line);
  entry.insert("inputs", toml::array{toml::table{{"file", fs::absolute(file).lexically_normal().string()},
                                                 {"sha256", sha256_file_hex(file)},
                                                 {"track", s.track},
                                                 {"points", fit.points}}});
  if (o.law == "paper") return write_paper_law(o, s, fit, file, what, std::move(entry));
  const double W = o.width, c0 = fit.c0, D = fit.D;
  if (!(D > 0.0))
    throw InputError(fmt::format(
        "{}: the fitted D = {:.4g} +- {:.2g} A^2/ps is not positive (c0 = {:.4g} +- {:.2g} A/ps, {} points): its growth "
        "speed rises with 1/R, i.e. the domain decelerates as it grows (R from {:.4g} to {:.4g} A). The well-posed "
        "phase-field model (Allen-Cahn gradient flow) has dR/dt = c0 - 2D/R with D > 0: a small domain grows slower "
        "than a flat front. Decelerating growth such as Xu et al. (2015)'s L ~ t^0.465 would need D < 0, the "
        "anti-diffusive sign of their eq 39 as printed, which has no well-posed field model (docs/theory/phasefield.md); "
        "--law paper fits their dR/dt = c0 + 2D/R and writes the sharp-front model (kind = sharp_front). Nothing written",
        what, D, fit.D_stderr, c0, fit.c0_stderr, fit.points, s.R.front(), s.R.back()));
  if (std::abs(c0) * W > D)
    throw InputError(fmt::format("{}: --interface-width {} A is wider than D/|c0| = {:.4g} A: a = (1 - c0 W/D)/2 would "
                                 "leave [0, 1] (c0 = {:.4g} A/ps, D = {:.4g} A^2/ps); choose a narrower front",
                                 what, W, D / std::abs(c0), c0, D));
  const double a = 0.5 * (1.0 - c0 * W / D), tau = W * W / (2.0 * D);
  // Propagated standard errors: ∂a/∂c₀ = −W/(2D), ∂a/∂D = c₀W/(2D²); ∂τ/∂D = −W²/(2D²).
  const double da_dc = -W / (2 * D), da_dD = c0 * W / (2 * D * D);
  const double a_err = std::sqrt(da_dc * da_dc * fit.c0_stderr * fit.c0_stderr + da_dD * da_dD * fit.D_stderr * fit.D_stderr +
                                 2 * da_dc * da_dD * fit.c0_D_covariance);
  const double tau_err = W * W / (2 * D * D) * fit.D_stderr;
  const std::string note = fmt::format(
      "phase-field model of the growth of track {} of {} (R from {:.4g} to {:.4g} A, t from {:.4g} to {:.4g} ps): "
      "dR/dt = c0 - 2D/R with c0 = {:.4g} A/ps, D = {:.4g} A^2/ps; front width W = {} A chosen; in the model's units "
      "(length 1 A, time tau) D = W^2/2 = {:.6g}, a as given",
      s.track, file.filename().string(), s.R.front(), s.R.back(), s.t.front(), s.t.back(), c0, D, W, 0.5 * W * W);
  toml::table t = fit_table(fit, 1.0, s, o);
  t.insert("law", "dR/dt = c0 - (n-1) D/R, n = 3 (v = c0 - D kappa, kappa = 2/R > 0 for a convex hcp domain; Xu et al. "
                  "(2015) eq 43 v = c0 + D k holds with k = -kappa)");
  t.insert("a", a), t.insert("a_stderr", a_err), t.insert("relaxation_time_stderr_s", tau_err * kPs);
  t.insert("interface_width_m", W * kA);
  if (c0 > 0) t.insert("critical_radius_m", 2 * D / c0 * kA);
  entry.insert("fit", t);
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "domain_growth",
                                    {{"phasefield.a", a}, {"phasefield.interface_width", W * kA},
                                     {"phasefield.relaxation_time", tau * kPs}},
                                    {{"phasefield.note", note}}, entry);
  std::printf("%s (%d points, t = %.4g ... %.4g ps, R = %.4g ... %.4g A)\n"
              "  dR/dt = c0 - 2D/R:  c0 = %.4g +- %.2g A/ps,  D = %.4g +- %.2g A^2/ps  (R0 = %.4g +- %.2g A, rms %.3g A)\n"
              "  critical radius 2D/c0 = %.4g A\n"
              "  model (length 1 A, time tau): a = %.4f +- %.4f, D = W^2/2 = %.6g, tau = %.4g +- %.2g ps (W = %g A)\n"
              "-> %s\n",
              what.c_str(), fit.points, s.t.front(), s.t.back(), s.R.front(), s.R.back(), c0, fit.c0_stderr, D,
              fit.D_stderr, fit.R0, fit.R0_stderr, fit.residual_rms, c0 > 0 ? 2 * D / c0 : INFINITY, a, a_err,
              0.5 * W * W, tau, tau_err, W, o.out.file.string().c_str());
}

}  // namespace

void add_bridge_domain_growth_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<DomainGrowthOptions>();
  CLI::App* cmd = bridge.add_subcommand(
      "domain-growth",
      "MD domain growth -> phase-field model (Xu et al. (2015) §4.4.3). Reads the tracks.csv of\n"
      "shockfield analyze atoms --clusters RC --cluster-select acna:hcp --track (times in ps: give\n"
      "--timestep-size in ps; or the tracks.csv of a phasefield run), takes the equivalent radius R(t)\n"
      "of one tracked domain and fits a growth law with standard errors:\n"
      "  --law allen_cahn (default): dR/dt = c0 - 2D/R, the sharp-interface law of the well-posed\n"
      "    field model (D > 0: a small domain grows slower than a flat front). With the front width\n"
      "    W you choose, the model's time unit is tau = W^2/(2D) and a = (1 - c0 W/D)/2. Writes\n"
      "    [phasefield] a, interface_width, relaxation_time. A fit with D <= 0 (decelerating growth,\n"
      "    as L ~ t^0.465) is refused: no well-posed field model has it.\n"
      "  --law paper: dR/dt = c0 + 2D/R, Xu et al. (2015) eq 43 as printed (D > 0: a small domain\n"
      "    grows faster), ill-posed for any shape but a sphere. Writes [phasefield] kind =\n"
      "    \"sharp_front\", law, front_speed, curvature_coefficient for [model] kind = \"sharp_front\"\n"
      "    (spheres only). No --interface-width.\n"
      "Both write [provenance.domain_growth] (tracks.csv and its SHA-256, the fit).\n"
      "Example: shockfield bridge domain-growth analysis --interface-width 2 --until 15 -o fe_pf.toml\n"
      "         shockfield bridge domain-growth analysis --law paper -o fe_paper.toml");
  cmd->add_option("tracks", o->tracks, "tracks.csv of analyze atoms --track, or its output folder")->required();
  cmd->add_option("--law", o->law,
                  "allen_cahn: dR/dt = c0 - 2D/R (the well-posed field model); paper: dR/dt = c0 + 2D/R (Xu et al. "
                  "(2015) eq 43, the sharp-front model)")
      ->capture_default_str()
      ->check(CLI::IsMember({"allen_cahn", "paper"}));
  cmd->add_option("--interface-width", o->width,
                  "Front width W (Å), --law allen_cahn only (required there): the logistic length sqrt(2 D tau) of "
                  "the model's tanh front; small against R (sharp-interface limit) and at most D/c0; resolve it with "
                  ">= 3 grid nodes")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--track", o->track, "The track to fit (default: the one with the most frames)")->check(CLI::PositiveNumber);
  cmd->add_option("--from", o->from, "Leave out points before this time (ps)");
  cmd->add_option("--until", o->until, "Leave out points after this time (ps): the fit time");
  cmd->add_option("--radius", o->radius,
                  "Which radius: atomic (the sphere of the atomic volume, N V/N_atoms) or moments (L = (abc)^(1/3))")
      ->capture_default_str()
      ->check(CLI::IsMember({"atomic", "moments"}));
  cmd->add_option("--time-scale", o->time_scale, "Picoseconds per unit of the time column of tracks.csv (1 for time_ps; the MD time step for "
                  "elapsed_timesteps; the model's time unit for a phasefield run's time)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_bridge_output_options(*cmd, o->out, "[phasefield]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
