#pragma once
// A thermo table as LAMMPS prints one: a header of column names, then one row per thermo step,
// every column right-aligned in a fixed width so the table reads (and greps, and loads with
// numpy.loadtxt) as columns.
#include <cstddef>
#include <string>
#include <vector>

namespace shockfield {

class ThermoTable {
 public:
  /// Column names, e.g. {"Step", "Time", "Temp", "PotEng", "TotEng", "Press"}; names must be
  /// non-empty and free of spaces (std::invalid_argument otherwise).
  explicit ThermoTable(std::vector<std::string> columns);

  /// The column names, each right-aligned in its column's width, separated by one space.
  std::string header() const;
  /// One row: a value that is an integer of magnitude below 1e15 is printed as an integer (steps,
  /// counts), any other as %.8g (NaN and inf as nan/inf); one value per column
  /// (std::invalid_argument otherwise). A value wider than its column widens only its own row.
  std::string row(const std::vector<double>& values) const;

  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::vector<std::string> columns_;
  std::vector<std::size_t> widths_;
};

}  // namespace shockfield
