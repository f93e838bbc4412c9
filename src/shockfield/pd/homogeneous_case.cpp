#include "shockfield/pd/homogeneous_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shockfield/core/error.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/run_session.hpp"
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

}  // namespace

void run_homogeneous(const Config& root, const RunOptions& options) {
  const Config material = root.table("material");
  if (material.get_choice_or("model", {"j2", "crystal", "pmb", "lps"}, "j2") != "crystal")
    material.fail("model", "[homogeneous] drives the crystal law: model = \"crystal\"");
  const CrystalSpec spec = read_crystal(material);
  if (spec.polycrystal)
    material.fail("orientation", "[homogeneous] is one material point: orientation = \"direction\", \"euler\" or "
                                 "\"random\" (with taylor_grains), not \"random_grains\"");
  const HomogeneousSpec h = read_homogeneous(root.table("homogeneous"));
  root.check_unknown_keys();
  if (options.resume || options.stop_after > 0)
    throw InputError("--resume and --stop-after: a [homogeneous] run keeps no checkpoint (it takes seconds); "
                     "run it again with --overwrite");
  const CrystalMaterial& m = spec.base;
  const auto grains = static_cast<long long>(m.aggregate.orientations.size());
  const long long steps = h.path.steps();
  root.derive("grains", grains);
  root.derive("steps", steps);
  root.derive("time_step_s", h.path.end_strain / h.path.strain_rate / static_cast<double>(steps));
  root.derive("openmp_threads", static_cast<long long>(omp_get_max_threads()));
  if (options.validate_only) {
    std::printf("%s: valid pd [homogeneous] case (%lld grains, %lld steps)\n", options.case_file.string().c_str(),
                grains, steps);
    return;
  }

  RunSession run = open_run_session(root, options, "pd",
                                    fmt::format("homogeneous compression (eq. 44), {} grains", grains));
  std::vector<std::string> grain_columns{"strain"};
  for (long long g = 0; g < grains; ++g) grain_columns.push_back(fmt::format("grain_{}_Pa", g));
  io::CsvWriter curve(run.folder / "stress_strain.csv",
                      {"strain", "time_s", "taylor_axial_Pa", "grain_sd_Pa", "grain_min_Pa", "grain_max_Pa",
                       "mean_accumulated_slip"});
  io::CsvWriter per_grain(run.folder / "grains.csv", grain_columns);
  Progress progress("pd homogeneous", 0, steps, !options.quiet);
  std::vector<double> axial(static_cast<std::size_t>(grains));
  long long rows = 0;
  double widest = 0.0, widest_at = 0.0, taylor = 0.0;
  // Loading along x, as in every pd run: eq. 44 with the seed's axis 3 taken as x.
  const materials::CompressionObserver observe = [&](long long k, double t, double strain,
                                                     const materials::TaylorAggregate::State& state,
                                                     const std::vector<Mat3>& sigma, const Mat3& average) {
    for (std::size_t g = 0; g < sigma.size(); ++g) axial[g] = materials::axial_stress(sigma[g], 0);
    taylor = materials::axial_stress(average, 0);
    const Spread s = spread(axial);
    if (s.max - s.min > widest) widest = s.max - s.min, widest_at = strain;
    progress.update(k);
    if (k != steps && std::abs(strain) + 1e-12 < static_cast<double>(rows) * h.output_increment) return;
    ++rows;
    curve.row({strain, t, taylor, s.sd, s.min, s.max, materials::TaylorAggregate::accumulated_slip(state)});
    std::vector<double> row{strain};
    row.insert(row.end(), axial.begin(), axial.end());
    per_grain.row(row);
  };
  const auto final_state = materials::compress_aggregate(m.aggregate, h.path, observe, 0);
  progress.finish(steps);
  write_grain_summary(run.folder / "grain_summary.csv", m, final_state, axial);
  const Spread end = spread(axial);
  run.log.info("finished: ε = {} after {} steps; Taylor axial stress {:.4g} MPa (eq. 45 of ⟨σ⟩, eq. 43); grains "
               "from {:.4g} to {:.4g} MPa (sd {:.3g} MPa); widest soft-hard spread {:.4g} MPa at ε = {:.3g}",
               h.path.end_strain, steps, taylor / 1e6, end.min / 1e6, end.max / 1e6, end.sd / 1e6, widest / 1e6,
               widest_at);
}

}  // namespace shockfield::pd
