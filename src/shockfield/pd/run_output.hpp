#pragma once
// Output of a PD run (docs/pd.md, "Outputs"): the time series series.csv (kinetic energy,
// momentum, peak axial compression and plastic measure) and point profiles
// profiles/profile_<k>.csv (position, displacement, velocity, Cauchy stress, pressure, plastic
// measure, grain and damage of every point) indexed with their times by profiles/index.csv; each
// profile is also a VTK PolyData file profiles/points_<k>.vtp at the deformed positions (the same
// fields, displacement as a vector, grain as Int32) indexed by profiles/points.pvd for ParaView,
// and with [output] dump = true a LAMMPS dump dumps/dump.<step>.lammpstrj (io/particle_frame).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "shockfield/core/output_schedule.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/particle_frame.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

/// What the output reads of the force model per point.
/// Empty stress and plastic functions (bond models) write NaN.
struct PointFields {
  std::function<Mat3(std::size_t)> stress;       ///< Cauchy σ [Pa]
  std::function<double(std::size_t)> plastic;    ///< accumulated plastic measure (ε̄p, or slip γ_tot) [-]
  std::vector<int> grain;                        ///< grain of each point (0 without grains)
  std::function<std::vector<double>()> damage;   ///< φ of every point (ForceModel::damage) [-]
};

/// Where a resumed run picks up its output.
struct ResumePoint {
  std::int64_t step = 0;
  std::int64_t profiles = 0;
  double time = 0.0;  ///< of the checkpoint: points.pvd keeps the frames written by then
};

class RunOutput {
 public:
  /// `dim`: the body's, for the per-length and per-area labels of the series' totals;
  /// `last_step`: the run's last step, the digits of the dump names.
  RunOutput(const std::filesystem::path& folder, int dim, PointFields fields, const OutputIntervals& output,
            long long last_step, std::optional<ResumePoint> resume);

  void write_series(const Simulation& sim);
  /// profiles/profile_<index>.csv and profiles/points_<index>.vtp (and the dump) at the current time.
  void write_profile(const Simulation& sim, std::int64_t index);

 private:
  Mat3 stress(std::size_t i) const;
  double plastic(std::size_t i) const;

  /// Per-point values of one profile, shared by the CSV and the .vtp.
  struct PointValues {
    std::vector<double> stress;    ///< 9 per point, row-major Cauchy σ [Pa]
    std::vector<double> pressure;  ///< −tr σ / 3 [Pa]
    std::vector<double> plastic;   ///< plastic measure [-]
    std::vector<double> damage;    ///< φ [-]
  };
  void write_points(const Simulation& sim, std::int64_t index, PointValues values);

  std::filesystem::path folder_;
  PointFields fields_;
  io::CsvWriter series_, index_;
  io::ParticleOutput points_;
};

}  // namespace shockfield::pd
