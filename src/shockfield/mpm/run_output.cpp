#include "shockfield/mpm/run_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "shockfield/analysis/field_statistics.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/vtk_pieces.hpp"
#include "shockfield/mpm/diagnostics.hpp"

namespace shockfield::mpm {

namespace fs = std::filesystem;

namespace {

std::string window_label(double h) { return fmt::format("h{:g}um", h * 1e6); }

void append_window(std::vector<double>& row, const WindowStats& w) {
  row.push_back(static_cast<double>(w.count));
  row.push_back(w.bulk_density);
  for (std::size_t q = 0; q < w.mean.size(); ++q) row.push_back(w.mean[q]), row.push_back(w.std[q]);
  row.insert(row.end(), w.gradients.begin(), w.gradients.end());
}

}  // namespace

RunOutput::RunOutput(const fs::path& folder, const MpmCase& c, std::optional<CavityTracker> cavity,
                     std::optional<ResumePoint> resume)
    : folder_(folder), case_(c), cavity_(std::move(cavity)) {
  double keep_step = 0.0;
  const double* keep = nullptr;
  if (resume) keep_step = static_cast<double>(resume->step), keep = &keep_step;
  series_ = io::CsvWriter(folder / "series.csv", columns(), keep);
  if (c.output.field_interval > 0.0) {
    fs::create_directories(folder / "fields");
    const double* keep_time = resume ? &resume->time : nullptr;
    grid_pvd_ = io::PvdSeries(folder / "grid.pvd", keep_time, "s");
    if (c.output.particles) particles_pvd_ = io::PvdSeries(folder / "particles.pvd", keep_time, "s");
  }
  if (!c.diagnostics.histogram_times.empty()) fs::create_directories(folder / "histograms");
  if (c.shock_front)
    shock_front_.emplace(folder, c.grid, *c.shock_front,
                         resume ? std::optional<std::int64_t>(resume->step) : std::nullopt);
}

std::optional<ShockHugoniot> RunOutput::write_hugoniot() const {
  if (!shock_front_) return std::nullopt;
  return shock_front_->finish();
}

std::optional<fs::path> RunOutput::hugoniot_file() const {
  if (!shock_front_) return std::nullopt;
  return shock_front_->toml_file();
}

std::vector<std::string> RunOutput::columns() const {
  const int dim = case_.grid.dim;
  const std::string per = units::si::per_missing_dimensions_column(dim);
  std::vector<std::string> cols{"step", "time_s", "dt_stable_s", "mass_kg" + per, "momentum_x_kg_m_s" + per,
                                "momentum_y_kg_m_s" + per};
  if (dim == 3) cols.emplace_back("momentum_z_kg_m_s");
  for (const char* c : {"kinetic_J", "internal_J", "total_J"}) cols.push_back(c + per);
  // Every column names its unit (docs/conventions.md): the squared velocity gradients in 1/s²
  // spelt `_per_s2`, totals in 2D per metre of thickness (`per`).
  const char* gradients[] = {"rot2_per_s2", "div2_per_s2", "strain_rate2_per_s2"};
  cols.emplace_back("top_m");
  cols.insert(cols.end(), std::begin(gradients), std::end(gradients));
  const auto quantities = window_quantities(dim);
  for (const char* where : {"bottom", "top"})
    for (double h : case_.diagnostics.windows.heights) {
      const std::string p = fmt::format("{}_{}_", where, window_label(h));
      cols.push_back(p + "count");
      cols.push_back(p + "bulk_density_kg_m3");
      for (const auto& q : quantities)
        cols.push_back(p + q.name + "_mean_" + q.unit), cols.push_back(p + q.name + "_std_" + q.unit);
      for (const char* g : gradients) cols.push_back(p + g);
    }
  if (cavity_)
    cols.insert(cols.end(), {dim == 3 ? "cavity_size_m3" : "cavity_size_m2", "cavity_horizontal_m", "cavity_vertical_m",
                             "collapsibility", "v_up_above_m_s", "v_down_below_m_s"});
  if (case_.diagnostics.ejecta)
    cols.insert(cols.end(), {"free_surface_m", "ejecta_mass_kg" + per, "ejecta_count", "ejecta_max_height_m"});
  if (case_.options.contact.enabled) cols.insert(cols.end(), {"contact_node_count", "contact_force_N" + per});
  return cols;
}

void RunOutput::write_series(const Simulation& sim) {
  const Particles& p = sim.particles();
  const int dim = case_.grid.dim, axis = dim - 1;
  const Totals t = totals(p);
  std::vector<double> row{static_cast<double>(sim.step_count()), sim.time(), sim.stable_time_step(), t.mass,
                          t.momentum[0], t.momentum[1]};
  if (dim == 3) row.push_back(t.momentum[2]);
  const double top = highest(p, axis);
  const double inf = std::numeric_limits<double>::infinity();
  const WindowStats all = window_stats(p, dim, -inf, inf, 1.0);
  row.insert(row.end(), {t.kinetic, t.internal, t.total(), top});
  row.insert(row.end(), all.gradients.begin(), all.gradients.end());
  const double area = window_cross_section(case_.grid);
  const double y1 = case_.diagnostics.windows.bottom;
  for (double h : case_.diagnostics.windows.heights) append_window(row, window_stats(p, dim, y1, y1 + h, area));
  for (double h : case_.diagnostics.windows.heights)
    append_window(row, window_stats(p, dim, top - h, std::nextafter(top, inf), area));
  if (cavity_) {
    const CavityMeasure m = cavity_->measure(p, sim.time());
    row.insert(row.end(), {m.size, m.horizontal, m.vertical, m.collapsibility, m.v_up_above, m.v_down_below});
  }
  if (case_.diagnostics.ejecta) {
    const Ejecta e = ejecta(p, sim.grid(), case_.diagnostics.ejecta_threshold);
    row.insert(row.end(), {e.surface, e.mass, e.count, e.max_height});
  }
  if (case_.options.contact.enabled)
    row.insert(row.end(), {static_cast<double>(sim.contact_stats().nodes), sim.contact_stats().force});
  series_.row(row);
  if (shock_front_) shock_front_->record(sim);
}

io::VtkImage grid_fields(const Simulation& sim) {
  const Grid& grid = sim.grid();
  const GridSpec& g = grid.spec();
  const Particles& p = sim.particles();
  io::VtkImage img;
  img.length_units = "m";
  for (int a = 0; a < 3; ++a) {
    img.points[static_cast<std::size_t>(a)] = static_cast<std::size_t>(grid.nodes(a));
    img.origin[static_cast<std::size_t>(a)] = g.origin[a];
    img.spacing[static_cast<std::size_t>(a)] = a < g.dim ? g.cell_size[a] : 1.0;
  }
  const std::size_t nn = grid.size();
  const int axis = g.dim - 1;
  const char* names[] = {"temperature", "pressure", "density", "plastic_work", "damage", "longitudinal_stress",
                         "longitudinal_deviator", "von_mises"};
  const char* units[] = {"K", "Pa", "kg/m3", "J/kg", "1", "Pa", "Pa", "Pa"};
  constexpr std::size_t ns = 8;
  std::vector<double> mass(nn, 0.0), scalars(ns * nn, 0.0), vel(3 * nn, 0.0), stress(9 * nn, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::array<Weights1D, 3> w{};
    for (int a = 0; a < g.dim; ++a) {
      w[static_cast<std::size_t>(a)] = LinearShape::evaluate(p.x[i][a] - g.origin[a], g.cell_size[a], 0.0);
      if (!grid.fit(a, w[static_cast<std::size_t>(a)])) return img;  // off the grid: no field frame
    }
    const Mat3 sigma = p.state[i].stress();
    const Mat3& dev = p.state[i].deviatoric.s;
    const double q[ns] = {p.state[i].temperature, -sigma.trace() / 3.0, p.density(i), p.state[i].plastic_work,
                          p.state[i].damage, sigma(axis, axis), dev(axis, axis), materials::von_mises(dev)};
    for (int c = 0; c < w[2].count; ++c)
      for (int b = 0; b < w[1].count; ++b)
        for (int a = 0; a < w[0].count; ++a) {
          const std::size_t n = grid.flat(grid.wrap(0, w[0].base + a), grid.wrap(1, w[1].base + b), grid.wrap(2, w[2].base + c));
          const double mw = p.mass[i] * w[0].w[static_cast<std::size_t>(a)] * w[1].w[static_cast<std::size_t>(b)] *
                            w[2].w[static_cast<std::size_t>(c)];
          mass[n] += mw;
          for (std::size_t k = 0; k < ns; ++k) scalars[k * nn + n] += mw * q[k];
          for (int d = 0; d < 3; ++d) vel[3 * n + static_cast<std::size_t>(d)] += mw * p.v[i][d];
          for (int r = 0; r < 3; ++r)
            for (int c2 = 0; c2 < 3; ++c2) stress[9 * n + static_cast<std::size_t>(3 * r + c2)] += mw * sigma(r, c2);
        }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double cell_volume = 1.0;
  for (int a = 0; a < g.dim; ++a) cell_volume *= g.cell_size[a];
  std::vector<double> mass_density(nn), vx(nn), vy(nn);
  img.hidden_points.assign(nn, false);
  for (std::size_t n = 0; n < nn; ++n) {
    const bool empty = !(mass[n] > 0.0);
    img.hidden_points[n] = empty;
    for (std::size_t k = 0; k < ns; ++k) scalars[k * nn + n] = empty ? nan : scalars[k * nn + n] / mass[n];
    for (std::size_t d = 0; d < 3; ++d) vel[3 * n + d] = empty ? nan : vel[3 * n + d] / mass[n];
    for (std::size_t d = 0; d < 9; ++d) stress[9 * n + d] = empty ? nan : stress[9 * n + d] / mass[n];
    mass_density[n] = mass[n] / cell_volume;
    vx[n] = vel[3 * n], vy[n] = vel[3 * n + 1];
  }
  for (std::size_t k = 0; k < ns; ++k)
    img.point_data.push_back({names[k], 1,
                              std::vector<double>(scalars.begin() + static_cast<long>(k * nn),
                                                  scalars.begin() + static_cast<long>((k + 1) * nn)),
                              units[k]});
  img.point_data.push_back({"vx", 1, std::move(vx), "m/s"});
  img.point_data.push_back({"vy", 1, std::move(vy), "m/s"});
  img.point_data.push_back({"mass_density", 1, std::move(mass_density), "kg/m3"});
  img.point_data.push_back({"velocity", 3, std::move(vel), "m/s"});
  img.point_data.push_back({"stress", 9, std::move(stress), "Pa"});
  return img;
}

void RunOutput::write_fields(const Simulation& sim) {
  const std::string grid_name = fmt::format("fields/grid_{:09d}", sim.step_count());
  grid_pvd_.add(sim.time(), io::write_image_frame(folder_, grid_name, grid_fields(sim), case_.output.vtk));
  if (!case_.output.particles) return;
  const Particles& p = sim.particles();
  const std::size_t n = p.size();
  const int axis = case_.grid.dim - 1;
  std::vector<double> xyz(3 * n), vel(3 * n), stress(9 * n), deviator(9 * n);
  std::vector<io::VtkArray> arrays;
  struct ScalarArray {
    const char* name;
    const char* unit;
    bool label = false;  ///< categorical: written as Int32
  };
  const ScalarArray scalar_arrays[] = {
      {"density", "kg/m3"}, {"pressure", "Pa"}, {"temperature", "K"}, {"plastic_work", "J/kg"},
      {"plastic_strain", "1"}, {"energy", "J/kg"}, {"material", "1", true}, {"body", "1", true}, {"damage", "1"},
      {"longitudinal_stress", "Pa"}, {"longitudinal_deviator", "Pa"}, {"von_mises", "Pa"}};
  for (const ScalarArray& a : scalar_arrays) arrays.push_back({a.name, 1, std::vector<double>(n), a.unit, a.label});
  for (std::size_t i = 0; i < n; ++i) {
    const auto& s = p.state[i];
    const Mat3 sigma = s.stress();
    const Mat3& dev = s.deviatoric.s;
    for (std::size_t d = 0; d < 3; ++d) xyz[3 * i + d] = p.x[i][static_cast<int>(d)], vel[3 * i + d] = p.v[i][static_cast<int>(d)];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const auto k = 9 * i + static_cast<std::size_t>(3 * r + c);  // row-major, as VTK reads a tensor
        stress[k] = sigma(r, c), deviator[k] = dev(r, c);
      }
    const double values[] = {p.density(i), -sigma.trace() / 3.0, s.temperature, s.plastic_work,
                             s.deviatoric.plastic_strain, s.energy, static_cast<double>(p.material[i]),
                             static_cast<double>(p.body[i]), s.damage,
                             sigma(axis, axis), dev(axis, axis), materials::von_mises(dev)};
    for (std::size_t k = 0; k < arrays.size(); ++k) arrays[k].values[i] = values[k];
  }
  arrays.push_back({"velocity", 3, std::move(vel), "m/s"});
  arrays.push_back({"stress", 9, std::move(stress), "Pa"});
  arrays.push_back({"deviator", 9, std::move(deviator), "Pa"});
  const std::string name = fmt::format("fields/particles_{:09d}", sim.step_count());
  particles_pvd_.add(sim.time(), io::write_points_frame(folder_, name, xyz, arrays, case_.output.vtk));
}

void RunOutput::write_histograms(const Simulation& sim, std::size_t index) {
  const Particles& p = sim.particles();
  const int dim = case_.grid.dim, axis = dim - 1;
  const double lo = case_.diagnostics.histogram_all ? -INFINITY : case_.diagnostics.windows.bottom;
  const double hi = case_.diagnostics.histogram_all ? INFINITY : lo + case_.diagnostics.windows.heights.at(0);
  const auto quantities = window_quantities(dim);
  io::CheckedOutput out(folder_ / "histograms" / fmt::format("hist_{}.csv", index));
  out << fmt::format("# t = {} s, particles with {} <= x[{}] < {} m\n", sim.time(), lo, axis, hi);
  out << "quantity,bin_lo,bin_hi,count,mean,std,skewness,kurtosis\n";
  for (std::size_t q = 0; q < quantities.size(); ++q) {
    analysis::GridField f;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.x[i][axis] >= lo && p.x[i][axis] < hi) f.values.push_back(quantity(p, i, q, dim));
    if (f.values.empty()) continue;
    f.n = {f.values.size(), 1, 1};
    const analysis::Moments m = analysis::moments(f);
    const bool flat = m.std == 0.0;
    const analysis::Histogram h = flat ? analysis::histogram(f, 1, m.mean - 0.5, m.mean + 0.5)
                                       : analysis::histogram(f, static_cast<std::size_t>(case_.diagnostics.histogram_bins));
    for (std::size_t b = 0; b < h.counts.size(); ++b)
      out << fmt::format("{}_{},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g}\n", quantities[q].name, quantities[q].unit, h.edges[b], h.edges[b + 1],
                         h.counts[b], m.mean, m.std, m.skewness, m.kurtosis);
  }
  out.close();
}

double window_cross_section(const GridSpec& g) {
  double s = 1.0;
  for (int a = 0; a + 1 < g.dim; ++a) s *= g.length(a);
  return s;
}

}  // namespace shockfield::mpm
