#include "shockfield/pd/homogeneous_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/pd/crystal_case.hpp"

namespace shockfield::pd {

namespace fs = std::filesystem;

HomogeneousSpec read_homogeneous(const Config& t) {
  HomogeneousSpec s;
  materials::CompressionPath& p = s.path;
  p.strain_rate = t.get_double_or("strain_rate", p.strain_rate, {});
  if (!(std::abs(p.strain_rate) > 0.0)) t.fail("strain_rate", "a non-zero ε̇ in 1/s (negative: compression)");
  p.end_strain = t.get_double("end_strain", Range::closed(-5.0, 5.0));
  if (!(p.end_strain * p.strain_rate > 0.0))
    t.fail("end_strain", fmt::format("{}: the last strain must have the sign of strain_rate = {} (ε = ε̇·t)",
                                     p.end_strain, p.strain_rate));
  p.strain_increment = t.get_double_or("strain_increment", p.strain_increment, {0.0, 0.01, true, false});
  s.output_increment = t.get_double_or("output_increment", s.output_increment, Range::positive());
  if (s.output_increment < p.strain_increment)
    t.fail("output_increment", fmt::format("{} is below strain_increment = {} (one row per step at most)",
                                           s.output_increment, p.strain_increment));
  return s;
}

namespace {

struct Spread {
  double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0;
};
Spread spread(const std::vector<double>& v) {
  Spread s{0.0, 0.0, *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(s.sd / static_cast<double>(v.size()));
  return s;
}

// Per grain: the crystal direction along the loading axis x before and after, its Schmid factor,
// the final axial stress (eq. 45) and accumulated slip (eq. 39).
void write_grain_summary(const fs::path& file, const CrystalMaterial& m,
                         const materials::TaylorAggregate::State& state, const std::vector<double>& axial) {
  io::CsvWriter out(file, {"grain", "axis_h", "axis_k", "axis_l", "final_axis_h", "final_axis_k", "final_axis_l",
                           "schmid_factor", "final_axial_Pa", "accumulated_slip"});
  for (std::size_t g = 0; g < state.size(); ++g) {
    const Vec3 a = state[g].orientation.transpose() * Vec3::UnitX();
    const Vec3 b = state[g].lattice.transpose() * Vec3::UnitX();
    CrystalMaterial one = m;
    one.aggregate.orientations = {state[g].orientation};
    out.row({static_cast<double>(g), a[0], a[1], a[2], b[0], b[1], b[2], schmid_factor_along_x(one), axial[g],
             state[g].accumulated_slip});
  }
}

// One material point driven along eq. 44 as a plug-in of the run driver: the whole compression
// is one advance() (it takes seconds and keeps no checkpoint).
class HomogeneousMethod final : public Method {
 public:
  HomogeneousMethod(const Config& root, const RunOptions& options) {
    const Config material = root.table("material");
    if (material.get_choice_or("model", {"j2", "crystal", "pmb", "lps"}, "j2") != "crystal")
      material.fail("model", "[homogeneous] drives the crystal law: model = \"crystal\"");
    const std::optional<materials::MaterialFile> file = materials::open_material_file(material);
    spec_ = read_crystal(material, file ? &*file : nullptr);
    // The file's path, SHA-256 and provenance: in [derived] by open_material_file, in log.txt by start().
    if (file) material_notes_ = file->summary_lines();
    if (spec_.polycrystal)
      material.fail("orientation", "[homogeneous] is one material point: orientation = \"direction\", \"euler\" or "
                                   "\"random\" (with taylor_grains), not \"random_grains\"");
    h_ = read_homogeneous(root.table("homogeneous"));
    root.check_unknown_keys();
    if (options.resume || options.stop_after > 0)
      throw InputError("--resume and --stop-after: a [homogeneous] run keeps no checkpoint (it takes seconds); "
                       "run it again with --overwrite");
    grains_ = static_cast<long long>(spec_.base.aggregate.orientations.size());
    steps_ = h_.path.steps();
    root.derive("grains", grains_);
    root.derive("steps", steps_);
    root.derive("time_step_s", h_.path.end_strain / h_.path.strain_rate / static_cast<double>(steps_));
  }

  std::string name() const override { return "pd"; }
  std::string size_text() const override {
    return fmt::format("homogeneous compression (eq. 44), {} grains", grains_);
  }
  std::string check_text() const override {
    return fmt::format("pd [homogeneous] case ({} grains, {} steps)", grains_, steps_);
  }
  void start(RunContext& run) override {
    run_ = &run;
    for (const std::string& note : material_notes_) run.log.info("material file: {}", note);
  }
  void resume(RunContext& run) override { run_ = &run; }  // refused by the constructor
  bool finished() const override { return done_ == steps_; }

  void advance() override {
    const fs::path& folder = run_->folder;
    std::vector<std::string> grain_columns{"strain"};
    for (long long g = 0; g < grains_; ++g) grain_columns.push_back(fmt::format("grain_{}_Pa", g));
    io::CsvWriter curve(folder / "stress_strain.csv",
                        {"strain", "time_s", "taylor_axial_Pa", "grain_sd_Pa", "grain_min_Pa", "grain_max_Pa",
                         "mean_accumulated_slip"});
    io::CsvWriter per_grain(folder / "grains.csv", grain_columns);
    axial_.assign(static_cast<std::size_t>(grains_), 0.0);
    long long rows = 0;
    // Loading along x, as in every pd run: eq. 44 with the paper's axis 3 taken as x.
    const materials::CompressionObserver observe = [&](long long k, double t, double strain,
                                                       const materials::TaylorAggregate::State& state,
                                                       const std::vector<Mat3>& sigma, const Mat3& average) {
      for (std::size_t g = 0; g < sigma.size(); ++g) axial_[g] = materials::axial_stress(sigma[g], 0);
      taylor_ = materials::axial_stress(average, 0);
      const Spread s = spread(axial_);
      if (s.max - s.min > widest_) widest_ = s.max - s.min, widest_at_ = strain;
      if (k != steps_ && std::abs(strain) + 1e-12 < static_cast<double>(rows) * h_.output_increment) return;
      ++rows;
      curve.row({strain, t, taylor_, s.sd, s.min, s.max, materials::TaylorAggregate::accumulated_slip(state)});
      std::vector<double> row{strain};
      row.insert(row.end(), axial_.begin(), axial_.end());
      per_grain.row(row);
    };
    const auto final_state = materials::compress_aggregate(spec_.base.aggregate, h_.path, observe, 0);
    write_grain_summary(folder / "grain_summary.csv", spec_.base, final_state, axial_);
    done_ = steps_;
  }

  void write_outputs() override {}
  std::int64_t step() const override { return done_; }
  std::string position() const override { return fmt::format(" (strain {})", done_ == steps_ ? h_.path.end_strain : 0.0); }
  std::int64_t steps_left() const override { return steps_ - done_; }
  std::int64_t checkpoint_every() const override { return 0; }
  void write_checkpoint(const fs::path&) override {}
  void log_results(double) override {
    const Spread end = spread(axial_);
    run_->log.info("finished: ε = {} after {} steps; Taylor axial stress {:.4g} MPa (eq. 45 of ⟨σ⟩, eq. 43); grains "
                   "from {:.4g} to {:.4g} MPa (sd {:.3g} MPa); widest soft-hard spread {:.4g} MPa at ε = {:.3g}",
                   h_.path.end_strain, steps_, taylor_ / 1e6, end.min / 1e6, end.max / 1e6, end.sd / 1e6,
                   widest_ / 1e6, widest_at_);
  }
  std::vector<std::string> thermo_columns() const override { return {"Step", "Strain", "TaylorAxial", "GrainSpread"}; }
  std::vector<double> thermo_values() const override {
    const Spread s = axial_.empty() ? Spread{} : spread(axial_);
    return {static_cast<double>(done_), done_ == steps_ ? h_.path.end_strain : 0.0, taylor_, s.max - s.min};
  }
  std::int64_t thermo_every() const override { return steps_; }
  double work_items() const override { return static_cast<double>(grains_); }
  std::string work_item_name() const override { return "grain"; }
  double time() const override { return done_ == steps_ ? h_.path.end_strain / h_.path.strain_rate : 0.0; }
  std::string time_unit() const override { return "s"; }
  Json results() const override {
    const Spread s = axial_.empty() ? Spread{} : spread(axial_);
    return Json::object()
        .set("end_strain", h_.path.end_strain)
        .set("taylor_axial_stress_Pa", taylor_)
        .set("grain_axial_stress_min_Pa", s.min)
        .set("grain_axial_stress_max_Pa", s.max)
        .set("grain_axial_stress_sd_Pa", s.sd)
        .set("widest_spread_Pa", widest_)
        .set("widest_spread_strain", widest_at_);
  }
  std::vector<std::string> resume_safe_keys() const override { return {}; }  // no checkpoint

 private:
  CrystalSpec spec_;
  HomogeneousSpec h_;
  long long grains_ = 0, steps_ = 0, done_ = 0;
  RunContext* run_ = nullptr;
  std::vector<double> axial_;
  std::vector<std::string> material_notes_;
  double widest_ = 0.0, widest_at_ = 0.0, taylor_ = 0.0;
};

}  // namespace

std::unique_ptr<Method> make_homogeneous_method(const Config& root, const RunOptions& options) {
  return std::make_unique<HomogeneousMethod>(root, options);
}

}  // namespace shockfield::pd
