#include "shockfield/phasefield/run_case.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/state_array.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_pieces.hpp"
#include "shockfield/phasefield/case_file.hpp"
#include "shockfield/phasefield/checkpoint.hpp"
#include "shockfield/phasefield/domain_measures.hpp"
#include "shockfield/phasefield/sharp_front_case.hpp"

namespace shockfield::phasefield {

namespace fs = std::filesystem;

namespace {

void derive(const Config& root, const PhasefieldCase& c) {
  root.derive("nodes", static_cast<long long>(c.grid.size()));
  root.derive("steps", c.steps);
  root.derive("explicit_time_step_limit", explicit_step_limit(c.grid, c.model));
  root.derive("reaction_time_step_limit", reaction_step_limit(c.model));
  root.derive("front_speed_c0", c.model.front_speed());
  root.derive("front_length", c.model.front_length());
  root.derive("nodes_per_front_length", c.model.front_length() / c.grid.dx);
  if (c.grid.dim > 1 && c.model.front_speed() > 0)
    root.derive("critical_radius", c.model.critical_radius(c.grid.dim));
  root.derive("initial_domains", static_cast<long long>(c.domains.size()));
}

// The well-posed Ginzburg–Landau model (docs/theory/phasefield.md) as a plug-in of the run driver:
// a whole number of steps of dt; series rows and frames at the first step at or past k·interval.
class PhasefieldMethod final : public Method {
 public:
  explicit PhasefieldMethod(const PhasefieldCase& c)
      : c_(c), solver_(c_.grid, c_.model, c_.scheme, c_.dt, false), tol_(kOutputTimeTolerance * c_.dt) {}

  std::string name() const override { return "phasefield"; }
  std::string size_text() const override {
    const auto& n = c_.grid.n;
    return fmt::format("{} nodes ({}D: {} x {} x {}), {} scheme, a {}, D {}", c_.grid.size(), c_.grid.dim, n[0], n[1],
                       n[2], scheme_name(c_.scheme), c_.model.a, c_.model.D);
  }
  std::string check_text() const override {
    return fmt::format("phasefield case ({} nodes, {} domains, {} steps, dt {:.3g}; {} when it runs)", c_.grid.size(),
                       c_.domains.size(), c_.steps, c_.dt, memory_text(Solver::bytes(c_.grid, c_.scheme)));
  }

  // The grid's arrays are allocated here, at the start, not by the factory (--check).
  void start(RunContext& run) override {
    allocate();
    solver_.field() = initial_field(c_.grid, c_.model, c_.domains, c_.field_file);
    solver_.hold_walls();
    open(run, false);
    write_due();
  }
  void resume(RunContext& run) override {
    allocate();
    counters_ = read_checkpoint(run.checkpoint, solver_);
    open(run, true);
  }
  bool finished() const override { return solver_.steps() >= c_.steps; }
  void advance() override { solver_.step(); }
  void check_health() override {
    for (const double v : solver_.field())
      if (!std::isfinite(v) || v < -1.0 || v > 2.0)
        throw RunError(fmt::format("xi = {} at step {} (t = {}): the step is unstable", v, solver_.steps(),
                                   solver_.time()));
  }
  void write_outputs() override { write_due(); }
  std::int64_t step() const override { return solver_.steps(); }
  std::string position() const override { return fmt::format(" (t = {})", solver_.time()); }
  double fraction_done() const override { return solver_.time() / c_.end_time; }
  std::int64_t steps_left() const override { return c_.steps - solver_.steps(); }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override { phasefield::write_checkpoint(file, solver_, counters_); }
  void write_final_outputs() override {
    if (c_.output.field_interval == 0.0) write_frame(counters_.frames++);
  }
  void log_results(double steps_per_second) override {
    const FieldMeasures m = solver_.measures();
    const char* per = units::model::per_missing_dimensions_text(c_.grid.dim);
    run_->log.info("finished: t = {} after {} steps ({:.3g} node-steps/s); hcp volume {}{} (fraction xi > 1/2: {}), "
                   "equivalent radius {}, free energy {}{}",
                   solver_.time(), solver_.steps(), steps_per_second * work_items(), m.integral, per,
                   m.fraction_above_half, equivalent_radius(m.integral, c_.grid.dim), m.free_energy, per);
  }

  std::vector<std::string> thermo_columns() const override {
    return {"Step", "Time", "FreeEng", "HcpVol", "HcpFrac", "Radius"};
  }
  std::vector<double> thermo_values() const override {
    const FieldMeasures m = solver_.measures();
    return {static_cast<double>(solver_.steps()), solver_.time(), m.free_energy, m.integral, m.fraction_above_half,
            equivalent_radius(m.integral, c_.grid.dim)};
  }
  std::int64_t thermo_every() const override { return thermo_interval(c_.output.thermo_every, c_.steps); }
  double work_items() const override { return static_cast<double>(c_.grid.size()); }
  std::string work_item_name() const override { return "node"; }
  std::vector<StateArray> state_arrays() override {
    solver_.keep_field_in_place();
    return {grid_state_array("xi", solver_.field(), c_.grid.dim, c_.grid.n)};
  }

  double time() const override { return solver_.time(); }
  std::string time_unit() const override { return "1"; }
  // The hcp domain totals of the last step (docs/phasefield.md, outputs).
  Json results() const override {
    const FieldMeasures m = solver_.measures();
    Json r = Json::object();
    const std::string per = units::model::per_missing_dimensions_column(c_.grid.dim);
    r.set("hcp_volume" + per, m.integral).set("volume_fraction", m.fraction_above_half);
    r.set("equivalent_radius", equivalent_radius(m.integral, c_.grid.dim)).set("free_energy" + per, m.free_energy);
    r.set("front_speed_c0", c_.model.front_speed());
    return r;
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"time.end_time", "output.*_interval", "output.thermo_every", "output.checkpoint_every"};
  }

 private:
  // The grid's arrays, and the pressure-dependent D read again from its file.
  void allocate() {
    solver_.allocate();
    if (!c_.pressure.file.path.empty()) solver_.set_diffusivity_scale(pressure_scale(c_.pressure, c_.grid));
  }
  void open(RunContext& run, bool resumed) {
    run_ = &run;
    const double keep_step = static_cast<double>(solver_.steps()), keep_time = solver_.time();
    const std::string per = units::model::per_missing_dimensions_column(c_.grid.dim);
    series_ = io::CsvWriter(run.folder / "series.csv",
                            {"step", "time", "volume_fraction", "free_energy" + per, "hcp_volume" + per, "equivalent_radius",
                             "surface", "mean_curvature", "euler", "axis_a", "axis_b", "axis_c", "long_axis_x",
                             "long_axis_y", "long_axis_z", "center_x", "center_y", "center_z"},
                            resumed ? &keep_step : nullptr);
    fs::create_directories(run.folder / "fields");
    pvd_ = io::PvdSeries(run.folder / "fields.pvd", resumed ? &keep_time : nullptr, "1");
    if (!finished())
      run.log.info("running to t = {} in {} steps of dt = {} ({} scheme; explicit limit {:.4g}; c0 = {:.6g})",
                   c_.end_time, c_.steps, c_.dt, scheme_name(c_.scheme), explicit_step_limit(c_.grid, c_.model),
                   c_.model.front_speed());
  }
  void write_due() {
    const double t = solver_.time() + tol_;
    write_due_frames(counters_.series, c_.output.series_interval, t, [&](auto) { write_row(); });
    write_due_frames(counters_.frames, c_.output.field_interval, t, [&](auto k) { write_frame(k); });
  }
  void write_row() {
    const FieldMeasures m = solver_.measures();
    const DomainMeasures shape = domain_measures(c_.grid, solver_.field());
    series_.row({static_cast<double>(solver_.steps()), solver_.time(), m.fraction_above_half, m.free_energy,
                 m.integral, equivalent_radius(m.integral, c_.grid.dim), shape.surface, shape.mean_curvature,
                 static_cast<double>(shape.euler), shape.semi_axes[0], shape.semi_axes[1], shape.semi_axes[2],
                 shape.long_axis[0], shape.long_axis[1], shape.long_axis[2], shape.center[0], shape.center[1],
                 shape.center[2]});
  }
  void write_frame(std::int64_t k) {
    write_xi_frame(run_->folder, c_.grid, solver_.field(), k, c_.output.vtk, solver_.time(), pvd_);
  }

  PhasefieldCase c_;
  Solver solver_;
  double tol_;
  OutputCounters counters_;
  io::CsvWriter series_;
  io::PvdSeries pvd_;
  RunContext* run_ = nullptr;
};

}  // namespace

void write_xi_frame(const fs::path& folder, const Grid& grid, const std::vector<double>& xi, std::int64_t k,
                    const io::VtkFormat& format, double time, io::PvdSeries& pvd) {
  io::VtkImage image;
  image.length_units = "1";  // model units
  for (int d = 0; d < 3; ++d) {
    image.points[d] = static_cast<std::size_t>(grid.n[d]);
    image.spacing[d] = grid.dx;
  }
  image.point_data.push_back({"xi", 1, xi, "1"});  // the order parameter, dimensionless
  pvd.add(time, io::write_image_frame(folder, fmt::format("fields/xi_{}", k), image, format));
}

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options) {
  if (is_sharp_front(root)) return make_sharp_front_method(root, options);
  const PhasefieldCase c = read_phasefield_case(root);
  root.check_unknown_keys();
  derive(root, c);
  return std::make_unique<PhasefieldMethod>(c);
}

}  // namespace shockfield::phasefield
