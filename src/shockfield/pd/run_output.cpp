#include "shockfield/pd/run_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace shockfield::pd {

namespace fs = std::filesystem;

RunOutput::RunOutput(const fs::path& folder, PointFields fields, std::optional<ResumePoint> resume)
    : folder_(folder), fields_(std::move(fields)) {
  fs::create_directories(folder / "profiles");
  const double keep_step = resume ? static_cast<double>(resume->step) : 0.0;
  // index.csv's first column is the profile number: keep those written before the checkpoint.
  const double keep_profile = resume ? static_cast<double>(resume->profiles) - 1.0 : 0.0;
  series_ = io::CsvWriter(folder / "series.csv",
                          {"step", "time_s", "kinetic_energy_J", "momentum_x", "momentum_y", "momentum_z",
                           "max_axial_compression_Pa", "max_plastic"},
                          resume ? &keep_step : nullptr);
  index_ = io::CsvWriter(folder / "profiles" / "index.csv", {"profile", "time_s", "step"},
                         resume ? &keep_profile : nullptr);
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
  const std::vector<double> damage = fields_.damage();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Mat3 s = stress(i);
    const Vec3& v = sim.velocities()[i];
    out.row({x[i][0], x[i][1], x[i][2], sim.positions()[i][0] - x[i][0], v[0], v[1], v[2], s(0, 0), s(1, 1), s(2, 2),
             s(0, 1), s(0, 2), s(1, 2), s.trace() / -3.0, plastic(i), static_cast<double>(fields_.grain[i]),
             damage[i]});
  }
  index_.row({static_cast<double>(index), sim.time(), static_cast<double>(sim.step_count())});
}

}  // namespace shockfield::pd
