// `shockfield bridge domain-growth TRACKS`: the growth of a tracked hcp domain of an MD series
// (`analyze atoms --clusters ... --track`, tracks.csv) → the phase-field model of Xu et al. (2015)
// §4.4.3 ([phasefield] a, interface_width, relaxation_time of a material file). The measured
// radius R(t) is fitted to the sharp-interface law of the well-posed model,
// Ṙ = c₀ − (n − 1) D/R (phasefield/growth_fit.hpp; docs/theory/phasefield.md), and the model's
// parameters follow from c₀ = √(D/(2τ))(1 − 2a) and the front width W = √(2Dτ) the user chooses:
// τ = W²/(2D), a = (1 − c₀W/D)/2. A fit with D ≤ 0 (a domain that decelerates as it grows) is
// refused: no well-posed gradient flow has it. docs/bridges.md §"bridge domain-growth".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  double width = 0;  ///< Å
  int track = 0;     ///< 0: the track with the most points
  double from = -INFINITY, until = INFINITY, time_scale = 1.0;
  std::string radius = "atomic";
  BridgeOutput out;
};

struct Series {
  int track = 0;
  std::vector<double> t, R;  ///< ps, Å
};

// The radius of each point of the chosen track in the time window.
Series read_track(const fs::path& file, const DomainGrowthOptions& o) {
  const auto cols = read_columns(file, {"track", "time", "size", "L", "atomic_volume"},
                                 "the tracks.csv of shockfield analyze atoms --clusters ... --track");
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

void run(const DomainGrowthOptions& o, const std::vector<std::string>& command_line) {
  const fs::path file = fs::is_directory(o.tracks) ? o.tracks / "tracks.csv" : o.tracks;
  if (!fs::exists(file))
    throw InputError(fmt::format("{}: no such file (expected the tracks.csv of shockfield analyze atoms --track, or its "
                                 "output folder)", file.string()));
  const Series s = read_track(file, o);
  const std::string what = fmt::format("{}: track {}", file.string(), s.track);
  const phasefield::GrowthFit fit = phasefield::fit_growth_law(s.t, s.R, 3, what);
  const double W = o.width, c0 = fit.c0, D = fit.D;
  if (!(D > 0.0))
    throw InputError(fmt::format(
        "{}: the fitted D = {:.4g} +- {:.2g} A^2/ps is not positive (c0 = {:.4g} +- {:.2g} A/ps, {} points): its growth "
        "speed rises with 1/R, i.e. the domain decelerates as it grows (R from {:.4g} to {:.4g} A). The well-posed "
        "phase-field model (Allen-Cahn gradient flow) has dR/dt = c0 - 2D/R with D > 0: a small domain grows slower "
        "than a flat front. Decelerating growth such as Xu et al. (2015)'s L ~ t^0.465 would need D < 0, the "
        "anti-diffusive sign of their eq 39 as printed, which has no well-posed model (docs/theory/phasefield.md). "
        "Nothing written",
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
  toml::table entry = materials::bridge_provenance_entry(command_line);
  entry.insert("inputs", toml::array{toml::table{{"file", fs::absolute(file).lexically_normal().string()},
                                                 {"sha256", sha256_file_hex(file)},
                                                 {"track", s.track},
                                                 {"points", fit.points}}});
  toml::table fit_table{
      {"law", "dR/dt = c0 - (n-1) D/R, n = 3 (v = c0 - D kappa, kappa = 2/R > 0 for a convex hcp domain; Xu et al. "
              "(2015) eq 43 v = c0 + D k holds with k = -kappa)"},
      {"radius", o.radius == "atomic" ? "equivalent sphere of the atomic volume, (3 V_atomic/4 pi)^(1/3)"
                                      : "moment size L = (abc)^(1/3)"},
      {"c0_m_s", c0 * kA / kPs}, {"c0_stderr_m_s", fit.c0_stderr * kA / kPs},
      {"D_m2_s", D * kA * kA / kPs}, {"D_stderr_m2_s", fit.D_stderr * kA * kA / kPs},
      {"c0_D_covariance_m3_s2", fit.c0_D_covariance * kA * kA * kA / (kPs * kPs)},
      {"R0_m", fit.R0 * kA}, {"R0_stderr_m", fit.R0_stderr * kA}, {"residual_rms_m", fit.residual_rms * kA},
      {"first_time_s", s.t.front() * kPs}, {"last_time_s", s.t.back() * kPs},
      {"first_radius_m", s.R.front() * kA}, {"last_radius_m", s.R.back() * kA},
      {"a", a}, {"a_stderr", a_err}, {"relaxation_time_stderr_s", tau_err * kPs},
      {"interface_width_m", W * kA}, {"converged", fit.converged}};
  if (c0 > 0) fit_table.insert("critical_radius_m", 2 * D / c0 * kA);
  entry.insert("fit", fit_table);
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
      "--timestep-size in ps), takes the equivalent radius R(t) of one tracked domain and fits the\n"
      "sharp-interface law of the well-posed model, dR/dt = c0 - 2D/R (D > 0: a small domain grows\n"
      "slower than a flat front), with standard errors. With the front width W you choose, the\n"
      "model's time unit is tau = W^2/(2D) and a = (1 - c0 W/D)/2. Writes [phasefield] a,\n"
      "interface_width, relaxation_time and [provenance.domain_growth] (tracks.csv and its SHA-256,\n"
      "the fit). A fit with D <= 0 (decelerating growth, as L ~ t^0.465) is refused.\n"
      "Example: shockfield bridge domain-growth analysis --interface-width 2 --until 15 -o fe_pf.toml");
  cmd->add_option("tracks", o->tracks, "tracks.csv of analyze atoms --track, or its output folder")->required();
  cmd->add_option("--interface-width", o->width,
                  "Front width W (Å): the logistic length sqrt(2 D tau) of the model's tanh front; small against R "
                  "(sharp-interface limit) and at most D/c0; resolve it with >= 3 grid nodes")
      ->required()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--track", o->track, "The track to fit (default: the one with the most frames)")->check(CLI::PositiveNumber);
  cmd->add_option("--from", o->from, "Leave out points before this time (ps)");
  cmd->add_option("--until", o->until, "Leave out points after this time (ps): the fit time");
  cmd->add_option("--radius", o->radius,
                  "Which radius: atomic (the sphere of the atomic volume, N V/N_atoms) or moments (L = (abc)^(1/3))")
      ->capture_default_str()
      ->check(CLI::IsMember({"atomic", "moments"}));
  cmd->add_option("--time-scale", o->time_scale, "Picoseconds per unit of the time column of tracks.csv")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_bridge_output_options(*cmd, o->out, "[phasefield]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
