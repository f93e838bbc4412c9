// `[model] kind = "sharp_front"` as a plug-in of the run driver (core/method.hpp): the spheres of
// sharp_front.hpp advanced by dt, series.csv (volume fraction, domain count, radii), tracks.csv
// in 3D (the columns of analyze atoms --track that bridge domain-growth reads), field frames of
// the hcp indicator (fields/xi_K.vti), thermo table, checkpoint.h5 (--resume continues bitwise).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/checkpoint_file.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/phasefield/checkpoint.hpp"
#include "shockfield/phasefield/run_case.hpp"
#include "shockfield/phasefield/sharp_front_case.hpp"

namespace shockfield::phasefield {

namespace fs = std::filesystem;

namespace {


void derive(const Config& root, const SharpFrontCase& c) {
  root.derive("steps", c.steps);
  root.derive("law_sign", c.law.sign());
  if (std::isfinite(c.law.fixed_radius())) root.derive("fixed_radius", c.law.fixed_radius());
  root.derive("initial_domains", static_cast<long long>(c.domains.size()));
}

class SharpFrontMethod final : public Method {
 public:
  explicit SharpFrontMethod(SharpFrontCase c) : c_(std::move(c)), tol_(kOutputTimeTolerance * c_.dt) {}

  std::string name() const override { return "phasefield"; }
  std::string size_text() const override {
    return fmt::format("{} sharp-front domains ({}D, law {}: dR/dt = c0 {} {}D/R, c0 {}, D {})", c_.domains.size(),
                       c_.grid.dim, front_law_name(c_.law.law), c_.law.sign() > 0 ? "+" : "-", c_.grid.dim - 1,
                       c_.law.c0, c_.law.D);
  }
  std::string check_text() const override {
    return fmt::format("phasefield sharp-front case ({} domains, law {}, {} steps, dt {:.3g}; {} grid nodes for the "
                       "outputs)", c_.domains.size(), front_law_name(c_.law.law), c_.steps, c_.dt, c_.grid.size());
  }

  void start(RunContext& run) override {
    domains_ = c_.domains;
    open(run, false);
    write_due();
  }
  void resume(RunContext& run) override {
    const io::CheckpointReader checkpoint(run.checkpoint);
    checkpoint.require("phasefield.sharp_front", kSharpFrontCheckpointFormat);
    // One track, radius and centre per domain; every value checked before it is used (a
    // positive track number, a finite positive radius, a finite centre).
    const io::Hdf5File& h5 = checkpoint.h5();
    const std::vector<std::int64_t> track = h5.read_ints("domain_track");
    const std::vector<double> radius = h5.read_doubles("domain_radius"), centre = h5.read_doubles("domain_centre");
    const auto bad = [&](const std::string& what) {
      return InputError(fmt::format("{}: domains: {}", run.checkpoint.string(), what));
    };
    if (radius.size() != track.size() || centre.size() != 3 * track.size())
      throw bad(fmt::format("{} tracks, {} radii and {} centre values; expected one radius and 3 centre values per "
                            "track", track.size(), radius.size(), centre.size()));
    domains_.clear();
    for (std::size_t m = 0; m < track.size(); ++m) {
      const double* x = &centre[3 * m];
      if (track[m] < 1 || !(radius[m] > 0 && std::isfinite(radius[m])) || !std::isfinite(x[0]) ||
          !std::isfinite(x[1]) || !std::isfinite(x[2]))
        throw bad(fmt::format("domain {} (track {}, radius {}) is not a track number, a positive radius and a finite centre",
                              m + 1, track[m], radius[m]));
      domains_.push_back({track[m], {x[0], x[1], x[2]}, radius[m]});
    }
    steps_ = checkpoint.count("step");
    counters_ = {checkpoint.count("series"), checkpoint.count("frames")};
    open(run, true);
  }
  bool finished() const override { return steps_ >= c_.steps; }
  void advance() override {
    advance_domains(c_.law, c_.dt, domains_);
    ++steps_;
  }
  void check_health() override {
    for (const SharpDomain& d : domains_)
      if (!std::isfinite(d.radius))
        throw RunError(fmt::format("domain {}: radius {} at step {} (t = {})", d.track, d.radius, steps_, time()));
  }
  void write_outputs() override { write_due(); }
  std::int64_t step() const override { return steps_; }
  std::string position() const override { return fmt::format(" (t = {})", time()); }
  double fraction_done() const override { return time() / c_.end_time; }
  std::int64_t steps_left() const override { return c_.steps - steps_; }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override {
    io::CheckpointWriter h5(file, "phasefield.sharp_front", kSharpFrontCheckpointFormat);
    h5.set_count("step", steps_);
    h5.set_attribute("time", time());
    h5.set_count("series", counters_.series);
    h5.set_count("frames", counters_.frames);
    std::vector<std::int64_t> track;
    std::vector<double> radius, centre;
    for (const SharpDomain& d : domains_) {
      track.push_back(d.track);
      radius.push_back(d.radius);
      centre.insert(centre.end(), {d.center[0], d.center[1], d.center[2]});
    }
    h5.write("domain_track", "1", track);
    h5.write("domain_radius", "1", radius);
    h5.write("domain_centre", "1", centre, {track.size(), 3});
    h5.commit();
  }
  void write_final_outputs() override {
    if (c_.output.field_interval == 0.0) write_frame(counters_.frames++);
  }
  void log_results(double steps_per_second) override {
    run_->log.info("finished: t = {} after {} steps ({:.3g} domain-steps/s); {} domains, largest radius {}, total volume {}{}",
                   time(), steps_, steps_per_second * work_items(), domains_.size(), largest_radius(), total_volume(),
                   units::model::per_missing_dimensions_text(c_.grid.dim));
  }

  std::vector<std::string> thermo_columns() const override { return {"Step", "Time", "Domains", "MaxRadius", "Volume"}; }
  std::vector<double> thermo_values() const override {
    return {static_cast<double>(steps_), time(), static_cast<double>(domains_.size()), largest_radius(), total_volume()};
  }
  std::int64_t thermo_every() const override { return thermo_interval(c_.output.thermo_every, c_.steps); }
  double work_items() const override { return static_cast<double>(std::max<std::size_t>(domains_.size(), 1)); }
  std::string work_item_name() const override { return "domain"; }

  // The clock is the step count (no sum of dt), so a resumed run has the same times bitwise.
  double time() const override { return static_cast<double>(steps_) * c_.dt; }
  std::string time_unit() const override { return "1"; }
  Json results() const override {
    Json r = Json::object();
    r.set("domains", static_cast<double>(domains_.size())).set("largest_radius", largest_radius());
    r.set("total_volume" + std::string(units::model::per_missing_dimensions_column(c_.grid.dim)), total_volume());
    r.set("law", front_law_name(c_.law.law));
    return r;
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"time.end_time", "output.*_interval", "output.thermo_every", "output.checkpoint_every"};
  }

 private:
  double largest_radius() const {
    double R = 0.0;
    for (const SharpDomain& d : domains_) R = std::max(R, d.radius);
    return R;
  }
  double total_volume() const {
    double V = 0.0;
    for (const SharpDomain& d : domains_) V += ball_volume(d.radius, c_.grid.dim);
    return V;
  }
  void open(RunContext& run, bool resumed) {
    run_ = &run;
    const double keep_step = static_cast<double>(steps_), keep_time = time();
    series_ = io::CsvWriter(run.folder / "series.csv",
                            {"step", "time", "volume_fraction", "overlap_fraction", "domains",
                             "total_volume" + std::string(units::model::per_missing_dimensions_column(c_.grid.dim)),
                             "equivalent_radius", "mean_radius", "max_radius"},
                            resumed ? &keep_step : nullptr);
    // tracks.csv with the columns of analyze atoms --track, the step first (so that a resumed run
    // keeps its rows up to the checkpoint); lengths in the grid's unit, times in the model's.
    if (c_.grid.dim == 3)
      tracks_ = io::CsvWriter(run.folder / "tracks.csv",
                              {"timestep", "time", "frame", "track", "cluster", "size", "x", "y", "z", "a", "b", "c", "L",
                               "area", "volume", "atomic_volume"},
                              resumed ? &keep_step : nullptr);
    fs::create_directories(run.folder / "fields");
    pvd_ = io::PvdSeries(run.folder / "fields.pvd", resumed ? &keep_time : nullptr, "1");
    if (!finished())
      run.log.info("running to t = {} in {} steps of dt = {} (sharp front, law {}: dR/dt = c0 {} {} D/R; fixed radius {:.6g})",
                   c_.end_time, c_.steps, c_.dt, front_law_name(c_.law.law), c_.law.sign() > 0 ? "+" : "-",
                   c_.grid.dim - 1, c_.law.fixed_radius());
  }
  void write_due() {
    const double t = time() + tol_;
    write_due_frames(counters_.series, c_.output.series_interval, t, [&](auto k) { write_rows(k); });
    write_due_frames(counters_.frames, c_.output.field_interval, t, [&](auto k) { write_frame(k); });
  }
  void write_rows(std::int64_t row) {
    const NodeCover cover = cover_nodes(c_.grid, domains_, false);
    const double n = static_cast<double>(domains_.size()), volume = total_volume();
    double sum = 0.0;
    for (const SharpDomain& d : domains_) sum += d.radius;
    series_.row({static_cast<double>(steps_), time(), cover.volume_fraction, cover.overlap_fraction, n, volume,
                 equivalent_radius(volume, c_.grid.dim), n > 0 ? sum / n : 0.0, largest_radius()});
    if (!tracks_.is_open()) return;
    for (std::size_t m = 0; m < domains_.size(); ++m) {
      const SharpDomain& d = domains_[m];
      const double R = d.radius, V = ball_volume(R, 3);
      tracks_.row({static_cast<double>(steps_), time(), static_cast<double>(row), static_cast<double>(d.track),
                   static_cast<double>(m + 1), static_cast<double>(cover.nodes_inside[m]), d.center[0], d.center[1],
                   d.center[2], R, R, R, R, 3.0 * V / R, V, V});
    }
  }
  void write_frame(std::int64_t k) {
    write_xi_frame(run_->folder, c_.grid, cover_nodes(c_.grid, domains_, true).indicator, k, c_.output.vtk, time(), pvd_);
  }

  SharpFrontCase c_;
  std::vector<SharpDomain> domains_;
  std::int64_t steps_ = 0;
  double tol_;
  OutputCounters counters_;
  io::CsvWriter series_, tracks_;
  io::PvdSeries pvd_;
  RunContext* run_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_sharp_front_method(const Config& root, const RunOptions&) {
  SharpFrontCase c = read_sharp_front_case(root);
  root.check_unknown_keys();
  derive(root, c);
  return std::make_unique<SharpFrontMethod>(std::move(c));
}

}  // namespace shockfield::phasefield
