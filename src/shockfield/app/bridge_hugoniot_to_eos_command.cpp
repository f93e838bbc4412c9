// `shockfield bridge hugoniot-to-eos RUN...`: MD Hugoniot states (the run folders of
// `shockfield hugoniot`, md/hugoniot_sweep.hpp) → a Mie-Grüneisen EOS (Xu et al. 2015, eqs. 5–6)
// in a material file. U_s = c0 + s·U_p by least squares with the standard errors and covariance
// of c0 and s (Press et al., Numerical Recipes, 3rd ed., §15.2 and §15.4: C = σ²(XᵀX)⁻¹ with
// σ² = χ²/(n − p)); a quadratic U_s = c0 + s·U_p + s2·U_p² when asked, or (--quadratic auto)
// when the data demand it: n ≥ 4 and |s2| > 3σ(s2). ρ0 is the MD density ahead of the shock.
// Γ0 is not on the Hugoniot: with --gamma0-md it is measured from the thermal pressure of the same
// potential and crystal at constant volume, Γ = V·ΔP/ΔE from two Langevin (NVT) runs at one
// volume and two temperatures (the definition Γ = V(∂P/∂E)_V), else taken from a library
// material; the file says which.
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "shockfield/app/commands.hpp"
#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/md/run_case.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;

struct EosOptions {
  std::vector<fs::path> inputs;
  BridgeOutput out;
  std::string quadratic = "auto";
  std::string gamma0_library = "copper";
  std::optional<double> gamma0;
  bool gamma0_md = false;
  std::vector<double> gamma0_temperatures{300.0, 600.0};
  long long gamma0_steps = 4000;
};

struct RunPoint {
  fs::path folder, hugoniot;
  std::string config_sha256;
  double up = 0, us = 0, rho0 = 0;  ///< km/s, km/s, kg/m³
};

// A sweep folder (`shockfield hugoniot` output) stands for its run folders: up_*/ (piston),
// us_*/ (msst) or p_*/ (nphug).
std::vector<fs::path> run_folders(const std::vector<fs::path>& inputs) {
  std::vector<fs::path> runs;
  for (const fs::path& in : inputs) {
    if (!fs::is_directory(in))
      throw InputError(fmt::format("{}: not a folder (expected an MD Hugoniot run folder or a `shockfield hugoniot` "
                                   "sweep folder)", in.string()));
    if (fs::exists(in / "config.resolved.toml")) {
      runs.push_back(in);
      continue;
    }
    std::vector<fs::path> sweep;
    for (const auto& e : fs::directory_iterator(in))
      for (const char* prefix : {"up_", "us_", "p_"})
        if (e.is_directory() && e.path().filename().string().rfind(prefix, 0) == 0) sweep.push_back(e.path());
    if (sweep.empty())
      throw InputError(fmt::format("{}: neither a run folder (no config.resolved.toml) nor a sweep folder (no up_*/, us_*/ "
                                   "or p_*/ run folders)", in.string()));
    std::sort(sweep.begin(), sweep.end());
    runs.insert(runs.end(), sweep.begin(), sweep.end());
  }
  return runs;
}

RunPoint read_run(const fs::path& folder) {
  RunPoint p;
  p.folder = fs::absolute(folder).lexically_normal();
  const fs::path resolved = folder / "config.resolved.toml";
  if (!fs::exists(resolved)) throw InputError(fmt::format("{}: no config.resolved.toml: not a run folder", folder.string()));
  const Config run = Config::load(resolved);
  const std::string method = run.get_string("method");
  if (method != "md")
    run.fail("method", fmt::format("\"{}\": hugoniot-to-eos reads MD Hugoniot runs (method = \"md\", the run folders "
                                   "of `shockfield hugoniot`)", method));
  std::vector<fs::path> states;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.path().filename().string().rfind("hugoniot_", 0) == 0 && e.path().extension() == ".toml") states.push_back(e.path());
  if (states.size() != 1)
    throw InputError(fmt::format("{}: expected one Hugoniot state hugoniot_<stage>.toml (written by an MD run with a "
                                 "[stage.piston], an msst or an nphug stage), found {}", folder.string(), states.size()));
  p.hugoniot = states.front();
  const Config h = Config::load(p.hugoniot);
  if (!h.get_bool("complete"))
    h.fail("complete", fmt::format("false: no complete Hugoniot state ({})", h.get_string_or("note", "")));
  // Speeds within 1000 km/s and densities within 0.001-1000 g/cm³ (a solid's are 0.5-23): beyond
  // them the fit's sums of squares lose every digit or overflow.
  p.up = h.get_double("up_km_s", {0.0, 1e3, true, false});
  p.us = h.get_double("us_km_s", {0.0, 1e3, true, false});
  p.rho0 = h.get_double("density0_g_cc", Range::closed(1e-3, 1e3)) * 1e3;
  h.get_double("piston_speed_km_s");
  p.config_sha256 = sha256_file_hex(resolved);
  return p;
}

// Polynomial least squares U_s = Σ_k b_k U_p^k (k < terms) with C = σ²(XᵀX)⁻¹, σ² = χ²/(n − terms).
struct PolyFit {
  Eigen::VectorXd coef;
  Eigen::MatrixXd cov;
  double rms = 0;  ///< √(χ²/n), km/s
};
std::string sources(const std::vector<RunPoint>& pts);
PolyFit fit_poly(const std::vector<RunPoint>& pts, int terms) {
  const auto n = static_cast<Eigen::Index>(pts.size());
  Eigen::MatrixXd x(n, terms);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int k = 0; k < terms; ++k) x(i, k) = std::pow(pts[static_cast<std::size_t>(i)].up, k);
    y(i) = pts[static_cast<std::size_t>(i)].us;
  }
  const Eigen::MatrixXd normal = x.transpose() * x;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
  if (!lu.isInvertible())
    throw InputError(fmt::format("the {} Hugoniot points ({}) have too few distinct particle velocities (up_km_s) "
                                 "for a fit with {} parameters", n, sources(pts), terms));
  PolyFit f;
  f.coef = lu.solve(x.transpose() * y);
  const double chi2 = (y - x * f.coef).squaredNorm();
  f.cov = chi2 / static_cast<double>(n - terms) * lu.inverse();
  f.rms = std::sqrt(chi2 / static_cast<double>(n));
  return f;
}

// Γ from MD: the first sweep run's resolved case as a periodic 4×4×4-cell crystal (same potential,
// lattice and a0: the sweep's initial volume) held at each temperature by Langevin dynamics;
// P and E averaged over the second half. Γ = V·(P2 − P1)/(E2 − E1); standard errors of the means
// from 10 blocks, propagated.
struct GammaMd {
  double gamma = 0, stderr = 0, density = 0;  ///< Γ, σ_Γ, ρ [kg/m³] of the runs
  toml::array runs;                           ///< per temperature: folder, T, P, E
};
GammaMd measure_gamma_md(const EosOptions& o, const RunPoint& first, const std::vector<std::string>& command_line) {
  toml::table base = toml::parse_file((first.folder / "config.resolved.toml").string());
  for (const char* drop : {"derived", "provenance", "stage", "output"}) base.erase(drop);
  toml::table* lattice = base.at_path("system.lattice").as_table();
  if (!lattice) throw InputError(fmt::format("{}: --gamma0-md needs a [system.lattice] crystal", first.folder.string()));
  lattice->insert_or_assign("boundary", "ppp");
  lattice->insert_or_assign("repeat", toml::array{4, 4, 4});
  GammaMd g;
  std::vector<std::array<double, 5>> means;  // T, P [bar], σP, E [eV], σE
  double volume = 0;
  for (double temperature : o.gamma0_temperatures) {
    toml::table c = base;
    c.insert_or_assign("velocity", toml::table{{"temperature", temperature}});
    c.insert_or_assign("output", toml::table{{"thermo_every", 10}});
    toml::array stages;
    stages.push_back(toml::table{{"name", "nvt"}, {"ensemble", "langevin"}, {"temperature", temperature},
                                 {"damping", 0.1}, {"steps", o.gamma0_steps}});
    c.insert_or_assign("stage", stages);
    const fs::path folder = fs::path(o.out.file).replace_extension("").string() + fmt::format("_gamma0/T_{:.0f}", temperature);
    fs::create_directories(folder);
    std::ostringstream text;
    text << c << "\n";
    io::replace_file(folder / "case.toml", text.str());
    RunOptions r;
    r.case_file = folder / "case.toml";
    r.output = folder / "run";
    r.overwrite = true;
    r.quiet = true;
    r.threads = 1;  // 256 atoms: threads cost more than they save
    r.command_line = command_line;
    const Config root = Config::load(r.case_file, {});
    root.get_choice("method", {"md"});
    md::run_case(root, r);
    const Config derived = Config::load(folder / "run" / "config.resolved.toml").table("derived");
    const double rho = derived.get_double("density_g_cc") * 1e3;
    g.density = rho;
    // thermo.csv: the second half of the rows, in 10 blocks.
    std::ifstream in(folder / "run" / "thermo.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) names.push_back(line);
    const auto col = [&](const char* n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
    std::vector<double> p, e;
    std::string row;
    while (std::getline(in, row)) {
      std::vector<double> v;
      for (std::stringstream ss(row); std::getline(ss, line, ',');) v.push_back(std::strtod(line.c_str(), nullptr));
      p.push_back(v[static_cast<std::size_t>(col("press_bar"))]);
      e.push_back(v[static_cast<std::size_t>(col("etotal_eV"))]);
      volume = v[static_cast<std::size_t>(col("volume_A3"))];
    }
    const std::size_t start = p.size() / 2, block = (p.size() - start) / 10;
    if (block < 2) throw RunError(fmt::format("{}: too few thermo rows for the averages", folder.string()));
    std::array<double, 5> m{temperature, 0, 0, 0, 0};
    for (int k = 0; k < 2; ++k) {
      const std::vector<double>& x = k == 0 ? p : e;
      std::vector<double> blocks(10, 0.0);
      for (std::size_t b = 0; b < 10; ++b)
        for (std::size_t i = 0; i < block; ++i) blocks[b] += x[start + b * block + i] / static_cast<double>(block);
      double mean = 0, var = 0;
      for (double v : blocks) mean += v / 10.0;
      for (double v : blocks) var += (v - mean) * (v - mean) / 9.0;
      m[static_cast<std::size_t>(1 + 2 * k)] = mean;
      m[static_cast<std::size_t>(2 + 2 * k)] = std::sqrt(var / 10.0);
    }
    means.push_back(m);
    g.runs.push_back(toml::table{{"folder", (folder / "run").string()},
                                 {"config_sha256", sha256_file_hex(folder / "run" / "config.resolved.toml")},
                                 {"temperature_K", temperature}, {"pressure_bar", m[1]}, {"pressure_stderr_bar", m[2]},
                                 {"energy_eV", m[3]}, {"energy_stderr_eV", m[4]}});
  }
  const auto& a = means.front();
  const auto& b = means.back();
  const double dp = (b[1] - a[1]) / units::metal::nktv2p, de = b[3] - a[3];  // eV/Å³, eV
  const double sdp = std::hypot(a[2], b[2]) / units::metal::nktv2p, sde = std::hypot(a[4], b[4]);
  g.gamma = volume * dp / de;
  g.stderr = std::abs(g.gamma) * std::hypot(sdp / dp, sde / de);
  return g;
}

std::string sources(const std::vector<RunPoint>& pts) {
  std::string s;
  for (const RunPoint& p : pts) s += (s.empty() ? "" : ", ") + p.hugoniot.string();
  return s;
}

void run(const EosOptions& o, const std::vector<std::string>& command_line) {
  std::vector<RunPoint> pts;
  for (const fs::path& f : run_folders(o.inputs)) pts.push_back(read_run(f));
  if (pts.size() < 3)
    throw InputError(fmt::format("{} Hugoniot point{} ({}): a U_s-U_p fit with uncertainties needs at least three "
                                 "piston speeds (shockfield hugoniot CASE --speeds a,b,c)",
                                 pts.size(), pts.size() == 1 ? "" : "s", sources(pts)));
  const PolyFit linear = fit_poly(pts, 2);
  std::optional<PolyFit> quad;
  if (pts.size() >= 4) quad = fit_poly(pts, 3);
  // |s2|/σ(s2); an exact fit (σ = 0) counts as demanding the term when s2 is not round-off.
  const double quad_sigma = quad ? std::sqrt(quad->cov(2, 2)) : 0.0;
  const double quad_ratio = !quad ? 0.0 : quad_sigma > 0 ? std::abs(quad->coef(2)) / quad_sigma
                                        : std::abs(quad->coef(2)) > 1e-9 ? INFINITY : 0.0;
  if (o.quadratic == "yes" && !quad)
    throw InputError(fmt::format("--quadratic yes: a quadratic fit with uncertainties needs at least four points, "
                                 "got {} ({})", pts.size(), sources(pts)));
  const bool use_quad = o.quadratic == "yes" || (o.quadratic == "auto" && quad && quad_ratio > 3.0);
  const PolyFit& fit = use_quad ? *quad : linear;
  const double c0 = fit.coef(0), s = fit.coef(1);
  const double us_max = std::max_element(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.us < b.us; })->us;
  if (s < 0)
    throw InputError(fmt::format("the U_s-U_p fit of us_km_s against up_km_s ({}) gives s = {:.4g} < 0: shock speed "
                                 "falling with piston speed is not a Mie-Gruneisen solid; check those runs",
                                 sources(pts), s));
  if (!(c0 > 0) || c0 > us_max)
    throw InputError(fmt::format("the U_s-U_p fit of us_km_s against up_km_s ({}) gives c0 = {:.4g} km/s, outside "
                                 "the range of the measured shock speeds (0, {:.4g}] km/s; check those runs",
                                 sources(pts), c0, us_max));
  double rho0 = 0, rho_var = 0;
  for (const RunPoint& p : pts) rho0 += p.rho0 / static_cast<double>(pts.size());
  for (const RunPoint& p : pts) rho_var += (p.rho0 - rho0) * (p.rho0 - rho0) / static_cast<double>(pts.size() - 1);
  double gamma0 = o.gamma0 ? *o.gamma0 : materials::make_material(o.gamma0_library).eos.gamma0;
  std::string gamma_note =
      o.gamma0 ? fmt::format("gamma0 = {} given on the command line (--gamma0), not measured by these MD runs", gamma0)
               : fmt::format("gamma0 = {} of the library material '{}' (docs/references.md), not measured by these MD "
                             "runs; rho*gamma = rho0*gamma0",
                             gamma0, o.gamma0_library);
  std::optional<GammaMd> gmd;
  if (o.gamma0_md) {
    gmd = measure_gamma_md(o, pts.front(), command_line);
    gamma0 = gmd->gamma * gmd->density / rho0;  // ργ = ρ0γ0: from the runs' density to rho0
    gamma_note = fmt::format("gamma0 = {:.4f} +- {:.4f} from MD: Gamma = V dP/dE at constant volume, two Langevin runs "
                             "of the same potential and crystal at {} K and {} K (rho = {:.1f} kg/m^3), scaled by "
                             "rho*gamma = rho0*gamma0",
                             gamma0, gmd->stderr * gmd->density / rho0, o.gamma0_temperatures.front(),
                             o.gamma0_temperatures.back(), gmd->density);
  }

  std::map<std::string, double> values{{"eos.rho0", rho0}, {"eos.c0", c0 * 1e3}, {"eos.s", s}, {"eos.gamma0", gamma0}};
  if (use_quad) values["eos.s2"] = fit.coef(2) * 1e-3;  // s/km → s/m
  toml::table entry = materials::bridge_provenance_entry(command_line);
  toml::array inputs;
  for (const RunPoint& p : pts)
    inputs.push_back(toml::table{{"folder", p.folder.string()},
                                 {"config_sha256", p.config_sha256},
                                 {"hugoniot", p.hugoniot.filename().string()},
                                 {"up_km_s", p.up},
                                 {"us_km_s", p.us},
                                 {"density0_kg_m3", p.rho0}});
  entry.insert("inputs", inputs);
  toml::table f{{"model", use_quad ? "quadratic" : "linear"},
                {"points", static_cast<int64_t>(pts.size())},
                {"c0_m_s", c0 * 1e3},
                {"c0_stderr_m_s", std::sqrt(fit.cov(0, 0)) * 1e3},
                {"s", s},
                {"s_stderr", std::sqrt(fit.cov(1, 1))},
                {"c0_s_covariance_m_s", fit.cov(0, 1) * 1e3},
                {"residual_rms_m_s", fit.rms * 1e3},
                {"rho0_stderr_kg_m3", std::sqrt(rho_var / static_cast<double>(pts.size()))},
                {"quadratic_criterion", "n >= 4 and |s2| > 3 sigma(s2)"},
                {"gamma0_source", gamma_note}};
  if (quad) {
    f.insert("quadratic_s2_s_m", quad->coef(2) * 1e-3);
    f.insert("quadratic_s2_stderr_s_m", std::sqrt(quad->cov(2, 2)) * 1e-3);
    f.insert("quadratic_s2_over_sigma", quad_ratio);
  }
  if (use_quad) f.insert("s2_stderr_s_m", std::sqrt(fit.cov(2, 2)) * 1e-3);
  if (gmd) {
    f.insert("gamma0_stderr", gmd->stderr * gmd->density / rho0);
    f.insert("gamma_md", gmd->gamma);  // at the runs' density
    f.insert("gamma_md_stderr", gmd->stderr);
    f.insert("gamma_md_density_kg_m3", gmd->density);
    f.insert("gamma0_md_runs", gmd->runs);
  }
  entry.insert("fit", f);
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "hugoniot_to_eos", values, {{"eos.note", gamma_note}},
                                    entry);
  std::printf("%zu Hugoniot points -> Us = c0 + s Up%s\n"
              "  c0     = %.4f +- %.4f km/s\n  s      = %.4f +- %.4f   (covariance c0-s %.3g km/s)\n",
              pts.size(), use_quad ? " + s2 Up^2" : "", c0, std::sqrt(fit.cov(0, 0)), s, std::sqrt(fit.cov(1, 1)),
              fit.cov(0, 1));
  if (use_quad) std::printf("  s2     = %.4f +- %.4f s/km\n", fit.coef(2), std::sqrt(fit.cov(2, 2)));
  else if (quad)
    std::printf("  (quadratic term s2 = %.3g +- %.3g s/km: %.2g sigma, linear kept)\n", quad->coef(2),
                std::sqrt(quad->cov(2, 2)), quad_ratio);
  std::printf("  rho0   = %.1f kg/m^3 (MD, ahead of the shock)\n  gamma0 = %s\n-> %s\n", rho0, gamma_note.c_str(),
              o.out.file.string().c_str());
}

}  // namespace

void add_bridge_hugoniot_to_eos_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<EosOptions>();
  CLI::App* cmd = bridge.add_subcommand(
      "hugoniot-to-eos",
      "MD Hugoniot sweep -> Mie-Gruneisen EOS. Reads the Hugoniot state (hugoniot_<stage>.toml:\n"
      "up_km_s, us_km_s, density0_g_cc) of each MD run folder (a `shockfield hugoniot` sweep folder\n"
      "stands for its up_*/, us_*/ or p_*/ runs; at least three points), fits Us = c0 + s Up by least squares and\n"
      "writes [eos] rho0 (MD density ahead of the shock), c0, s, gamma0 with the fit's standard\n"
      "errors and c0-s covariance, every input folder and the SHA-256 of its config.resolved.toml in\n"
      "[provenance.hugoniot_to_eos]. --quadratic auto (default) adds s2 Up^2 when n >= 4 and\n"
      "|s2| > 3 sigma(s2); MPM reads only linear fits. gamma0 is not on the Hugoniot: --gamma0-md\n"
      "measures it by MD (Gamma = V dP/dE at constant volume, two Langevin runs), else it is taken\n"
      "from a library material (--gamma0-library) or --gamma0; the file says which. Refused:\n"
      "fewer than three speeds, folders of another method, s < 0, c0 outside (0, max Us].\n"
      "Example: shockfield bridge hugoniot-to-eos runs/cu_hugoniot -o cu_md.toml");
  cmd->add_option("runs", o->inputs, "MD Hugoniot run folders or `shockfield hugoniot` sweep folders")->required();
  add_bridge_output_options(*cmd, o->out, "[eos]");
  cmd->add_option("--quadratic", o->quadratic, "Quadratic Us-Up term: auto (when the data demand it), yes, no")
      ->check(CLI::IsMember({"auto", "yes", "no"}))
      ->capture_default_str();
  cmd->add_option("--gamma0-library", o->gamma0_library, "Library material whose gamma0 is written")
      ->check(CLI::IsMember(materials::material_names()))
      ->capture_default_str();
  cmd->add_option("--gamma0", o->gamma0, "gamma0 to write instead of the library's")->check(CLI::Range(0.0, 10.0));
  cmd->add_flag("--gamma0-md", o->gamma0_md,
                "Measure gamma0 by MD: Gamma = V dP/dE from two Langevin runs of the first run's potential and "
                "crystal (periodic, 4x4x4 cells, its initial volume) at two temperatures; runs go to "
                "<output>_gamma0/");
  cmd->add_option("--gamma0-md-temperatures", o->gamma0_temperatures, "The two temperatures, K")
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--gamma0-md-steps", o->gamma0_steps, "Steps of each run (1 fs each)")
      ->check(CLI::Range(200, 10000000))
      ->capture_default_str();
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
