#include "shockfield/dbm/gls_run.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/dbm/phase_separation.hpp"
#include "shockfield/io/csv_writer.hpp"

namespace shockfield::dbm {

namespace fs = std::filesystem;

GlsRunPart::GlsRunPart(Simulation& sim, const DbmCase& c)
    : sim_(sim), force_(sim, c.boundaries, c.gls->settings), spec_(*c.gls) {}

void GlsRunPart::initialize(Simulation& sim) const {
  const Lattice& lattice = sim.lattice();
  const QuenchNoise xi = spec_.quench.noise_field(lattice);
  sim.initialize([&](double x, double y) { return spec_.quench.state(xi, x, y); });
}

std::vector<std::string> GlsRunPart::series_columns() const {
  std::vector<std::string> columns{"step", "time", "D", "D_force", "D_gradient", "L", "R", "density_variance",
                                   "rho_min", "rho_max", "T_mean", "v_max"};
  for (const char* total : {"mass", "energy"})
    columns.push_back(total + std::string(units::model::per_missing_dimensions_column(Lattice::dim)));
  for (const double level : spec_.extra_thresholds) columns.push_back(fmt::format("L_rho{}", level));
  return columns;
}

std::vector<double> GlsRunPart::series_row(const Simulation& sim) {
  const PhaseSample s = sample_phase_separation(sim, force_, spec_.threshold);
  const Lattice& l = sim.lattice();
  double lo = INFINITY, hi = 0.0, T = 0.0, u = 0.0;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = sim.macro(i, j);
      lo = std::min(lo, m.rho), hi = std::max(hi, m.rho), T += m.T;
      u = std::max(u, std::hypot(m.ux, m.uy));
    }
  T /= static_cast<double>(l.nx) * l.ny;
  std::vector<double> row{static_cast<double>(sim.steps()), s.t, s.D, s.D_force, s.D_gradient, s.boundary_length,
                          s.domain_size, s.density_variance, lo, hi, T, u, s.mass, s.energy};
  if (!spec_.extra_thresholds.empty())
    for (const analysis::Functionals2D& m : analysis::minkowski_2d(density_field(sim), spec_.extra_thresholds))
      row.push_back(m.boundary_length);
  return row;
}

std::vector<io::VtkArray> GlsRunPart::field_arrays() {
  const GlsTne tne = force_.tne();
  return {{"D", 1, tne.net.strength, "1"}, {"D_force", 1, tne.force.strength, "1"}};
}

const char* GlsRunPart::blow_up_hint() {
  return "GLS runs break down (docs/dbm.md, \"When a GLS run blows up\") when the interfaces are under-resolved "
         "(width ~ 2 sqrt(2K/|dP/drho|_T) should span 4 or more cells: raise K or refine dx), when tau is long for "
         "the grid (keep tau (pi/dx) sqrt(2T) near 0.3 or below and raise the heat conduction with q < 0 instead), "
         "when coalescing domains drive fast flows (the bulk viscosity zeta damps them), or with [model] filter_state = "
         "false (grid-scale modes of T then grow undamped)";
}

namespace {

// Columns `names` of a CSV file written by io::CsvWriter (header line, then numbers).
std::vector<std::vector<double>> read_columns(const fs::path& file, const std::vector<std::string>& names) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) throw RunError(fmt::format("cannot read '{}'", file.string()));
  std::vector<std::string> header;
  for (std::stringstream ss(line); std::getline(ss, line, ',');) header.push_back(line);
  std::vector<std::size_t> index;
  for (const std::string& n : names)
    index.push_back(static_cast<std::size_t>(std::find(header.begin(), header.end(), n) - header.begin()));
  std::vector<std::vector<double>> columns(names.size());
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) row.push_back(std::stod(line));
    for (std::size_t c = 0; c < names.size(); ++c) columns[c].push_back(row.at(index[c]));
  }
  return columns;
}

}  // namespace

PhaseSummary write_phase_summary(const fs::path& folder, const GlsCaseSpec& spec, Logger& log) {
  const auto col = read_columns(folder / "series.csv", {"time", "D", "D_force", "L", "R"});
  std::vector<PhaseSample> samples(col[0].size()), force(col[0].size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    samples[k].t = force[k].t = col[0][k];
    samples[k].D = col[1][k], force[k].D = col[2][k];
    samples[k].boundary_length = col[3][k];
    samples[k].domain_size = col[4][k];
  }
  const SpinodalEnd e = spinodal_end(samples), f = spinodal_end(force);
  const DomainGrowth g = domain_growth(samples, e.t_sd, spec.growth_window);
  io::CsvWriter csv(folder / "summary.csv", {"t_SD", "D_max", "R_SD", "t_SD_force", "D_force_max", "t_L_max", "L_max",
                                             "u_DG", "t_DG_begin", "t_DG_end"});
  csv.row({e.t_sd, e.D_max, e.R_sd, f.t_sd, f.D_max, e.t_L_max, e.L_max, g.speed, g.t_begin, g.t_end});
  log.info("phase separation: t_SD = {} (peak of D, D_max = {}, R_SD = {}), peak of D^F at t = {} ({}), peak of L at "
           "t = {} (L_max = {}, threshold {}), u_DG = {} (slope of R over t = {} to {})",
           e.t_sd, e.D_max, e.R_sd, f.t_sd, f.D_max, e.t_L_max, e.L_max, spec.threshold, g.speed, g.t_begin, g.t_end);
  return {e, f, g};
}

Json phase_summary_json(const PhaseSummary& s) {
  Json j = Json::object();
  j.set("t_SD", s.net.t_sd).set("R_SD", s.net.R_sd).set("D_max", s.net.D_max);
  j.set("t_SD_force", s.force.t_sd).set("D_force_max", s.force.D_max).set("t_L_max", s.net.t_L_max);
  j.set("u_DG", s.growth.speed).set("t_DG_begin", s.growth.t_begin).set("t_DG_end", s.growth.t_end);
  return j;
}

}  // namespace shockfield::dbm
