#pragma once
// Output of an MPM run (docs/mpm.md, "Outputs"): the time series series.csv (totals, window
// statistics, gradient mean squares, cavity and ejecta columns), grid fields as VTK ImageData
// (fields/grid_<step>.vti, indexed by grid.pvd) and particles as VTK PolyData
// (fields/particles_<step>.vtp, particles.pvd), and histograms with moments at chosen times
// (histograms/hist_<k>.csv); with [shock_front], shock_front.csv beside each series row and
// hugoniot_<material>.toml at the end (shock_front_output.hpp).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/mpm/case_file.hpp"
#include "shockfield/mpm/cavity_tracker.hpp"
#include "shockfield/mpm/shock_front_output.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace shockfield::mpm {

/// Where a resumed run picks up its output.
struct ResumePoint {
  std::int64_t step = 0;
  double time = 0.0;
};

class RunOutput {
 public:
  /// `cavity`: the tracker of the case's cavity, if it has one.
  RunOutput(const std::filesystem::path& folder, const MpmCase& c, std::optional<CavityTracker> cavity,
            std::optional<ResumePoint> resume);

  /// A series.csv row, and with [shock_front] a shock_front.csv row.
  void write_series(const Simulation& sim);
  /// With [shock_front]: the fit of every shock_front.csv row, written as its toml.
  std::optional<ShockHugoniot> write_hugoniot() const;
  std::optional<std::filesystem::path> hugoniot_file() const;
  void write_fields(const Simulation& sim);
  /// Histograms of the quantities at the current time; `index` numbers the file.
  void write_histograms(const Simulation& sim, std::size_t index);

  const std::vector<std::string>& series_columns() const { return series_.columns(); }
  std::optional<CavityTracker>& cavity() { return cavity_; }

 private:
  std::vector<std::string> columns() const;
  std::filesystem::path folder_;
  const MpmCase& case_;
  std::optional<CavityTracker> cavity_;
  io::CsvWriter series_;
  io::PvdSeries grid_pvd_, particles_pvd_;
  std::optional<ShockFrontOutput> shock_front_;
};

/// The lateral measure of a measurement window (width in 2D, area in 3D; 1 in 1D) [m^(dim-1)].
double window_cross_section(const GridSpec& g);

/// Particle data projected to the grid nodes with the linear shape functions (eq. 9), mass
/// weighted: temperature, pressure, density, specific plastic work, damage, the longitudinal stress
/// and deviator, von Mises stress, velocity, the Cauchy stress tensor, and the nodal mass
/// density Σ m_p N_i / V_cell. Nodes no particle reaches are NaN (void).
io::VtkImage grid_fields(const Simulation& sim);

}  // namespace shockfield::mpm
