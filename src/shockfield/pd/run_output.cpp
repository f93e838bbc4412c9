#include "shockfield/pd/run_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "shockfield/core/units.hpp"

namespace shockfield::pd {

namespace fs = std::filesystem;

RunOutput::RunOutput(const fs::path& folder, int dim, PointFields fields, const OutputIntervals& output,
                     long long last_step, std::optional<ResumePoint> resume)
    : folder_(folder), fields_(std::move(fields)) {
  fs::create_directories(folder / "profiles");
  const double keep_step = resume ? static_cast<double>(resume->step) : 0.0;
  // index.csv's first column is the profile number: keep those written before the checkpoint.
  const double keep_profile = resume ? static_cast<double>(resume->profiles) - 1.0 : 0.0;
  const std::string per = units::si::per_missing_dimensions_column(dim);
  series_ = io::CsvWriter(folder / "series.csv",
                          {"step", "time_s", "kinetic_energy_J" + per, "momentum_x_kg_m_s" + per,
                           "momentum_y_kg_m_s" + per, "momentum_z_kg_m_s" + per, "max_axial_compression_Pa",
                           "max_plastic"},
                          resume ? &keep_step : nullptr);
  index_ = io::CsvWriter(folder / "profiles" / "index.csv", {"profile", "time_s", "step"},
                         resume ? &keep_profile : nullptr);
  points_ = io::ParticleOutput(folder, folder / "profiles", "points", output.vtk, output.dumps,
                              io::step_digits(last_step), resume ? &resume->time : nullptr);
}

Mat3 RunOutput::stress(std::size_t i) const {
  return fields_.stress ? fields_.stress(i) : Mat3::Constant(std::numeric_limits<double>::quiet_NaN());
}

double RunOutput::plastic(std::size_t i) const {
  return fields_.plastic ? fields_.plastic(i) : std::numeric_limits<double>::quiet_NaN();
}

void RunOutput::write_series(const Simulation& sim) {
  // NaN for a field the model does not have (std::fmax keeps it), else the largest value and 0.
  const double none = std::numeric_limits<double>::quiet_NaN();
  double compression = fields_.stress ? 0.0 : none, most_plastic = fields_.plastic ? 0.0 : none;
  for (std::size_t i = 0; i < sim.cloud().size(); ++i) {
    compression = std::fmax(compression, -stress(i)(0, 0));
    most_plastic = std::fmax(most_plastic, plastic(i));
  }
  const Vec3 p = sim.momentum();
  series_.row({static_cast<double>(sim.step_count()), sim.time(), sim.kinetic_energy(), p[0], p[1], p[2], compression,
               most_plastic});
}

void RunOutput::write_profile(const Simulation& sim, std::int64_t index) {
  io::CsvWriter out(folder_ / "profiles" / fmt::format("profile_{}.csv", index),
                    {"x_m", "y_m", "z_m", "ux_m", "vx_m_s", "vy_m_s", "vz_m_s", "sxx_Pa", "syy_Pa", "szz_Pa", "sxy_Pa",
                     "sxz_Pa", "syz_Pa", "pressure_Pa", "plastic", "grain", "damage"});
  const auto& x = sim.cloud().x;
  const std::size_t n = x.size();
  // The model's stress and plastic measure of every point, evaluated once for the CSV and the .vtp.
  PointValues values{std::vector<double>(9 * n), std::vector<double>(n), std::vector<double>(n), fields_.damage()};
  for (std::size_t i = 0; i < n; ++i) {
    const Mat3 s = stress(i);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) values.stress[9 * i + static_cast<std::size_t>(3 * r + c)] = s(r, c);  // row-major
    values.pressure[i] = s.trace() / -3.0;
    values.plastic[i] = plastic(i);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double* s = &values.stress[9 * i];
    const Vec3& v = sim.velocities()[i];
    out.row({x[i][0], x[i][1], x[i][2], sim.positions()[i][0] - x[i][0], v[0], v[1], v[2], s[0], s[4], s[8], s[1], s[2],
             s[5], values.pressure[i], values.plastic[i], static_cast<double>(fields_.grain[i]), values.damage[i]});
  }
  write_points(sim, index, std::move(values));
  index_.row({static_cast<double>(index), sim.time(), static_cast<double>(sim.step_count())});
}

void RunOutput::write_points(const Simulation& sim, std::int64_t index, PointValues values) {
  const std::size_t n = sim.cloud().size();
  std::vector<double> xyz(3 * n), displacement(3 * n), velocity(3 * n), grain(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      const std::size_t k = 3 * i + static_cast<std::size_t>(d);
      xyz[k] = sim.positions()[i][d];
      displacement[k] = sim.positions()[i][d] - sim.cloud().x[i][d];
      velocity[k] = sim.velocities()[i][d];
    }
    grain[i] = fields_.grain[i];
  }
  io::ParticleFrame frame{sim.step_count(), sim.time(), std::move(xyz), {}, sim.cloud().spacing / 2,
                          {{"displacement", 3, std::move(displacement), "m"},
                           {"velocity", 3, std::move(velocity), "m/s"},
                           {"stress", 9, std::move(values.stress), "Pa"},
                           {"pressure", 1, std::move(values.pressure), "Pa"},
                           {"plastic", 1, std::move(values.plastic), "1"},
                           {"grain", 1, std::move(grain), "1", true},
                           {"damage", 1, std::move(values.damage), "1"}}};
  points_.write(frame, index);
}

}  // namespace shockfield::pd
