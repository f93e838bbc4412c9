#pragma once
// The shock-front tool in a run ([shock_front], docs/mpm.md "Shock front and Hugoniot"): with each
// series row, the profiled body's front, impact face, free end, the state ahead and the plateaus
// of that frame (shock_front.hpp) as a row of shock_front.csv; at the end of the run the rows are
// read back (a resumed run's too) and fitted, and the Hugoniot state is written as
// hugoniot_<material>.toml.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "shockfield/io/csv_writer.hpp"
#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/shock_front.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace shockfield::mpm {

class ShockFrontOutput {
 public:
  /// `resume_step`: keep the rows up to this step of a resumed run.
  ShockFrontOutput(const std::filesystem::path& folder, const GridSpec& grid, ShockFrontSpec spec,
                   std::optional<std::int64_t> resume_step);
  void record(const Simulation& sim);
  /// Fits every row of shock_front.csv and writes the toml.
  ShockHugoniot finish() const;
  std::filesystem::path toml_file() const { return folder_ / ("hugoniot_" + spec_.material + ".toml"); }

 private:
  std::filesystem::path folder_;
  GridSpec grid_;
  ShockFrontSpec spec_;
  io::CsvWriter csv_;
};

}  // namespace shockfield::mpm
