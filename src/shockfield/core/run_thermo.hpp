#pragma once
// The thermo table of a run (LAMMPS-like): the method's columns (Method::thermo_columns) every
// thermo_every steps and at the end, in log.txt and on the screen (not with --quiet), and in
// thermo.csv unless the method writes that file itself (MD). A resumed run keeps the rows up to
// its checkpoint.
#include <cstdint>

#include "shockfield/core/method.hpp"
#include "shockfield/core/thermo_table.hpp"
#include "shockfield/io/csv_writer.hpp"

namespace shockfield {

class RunThermo {
 public:
  /// Prints the header (and the first row of a fresh run).
  RunThermo(RunContext& run, const Method& method);
  /// A row if the step is on the schedule.
  void at_step();
  /// The last row, if the schedule did not just write it.
  void at_end();
  std::int64_t every() const { return every_; }

 private:
  void row();
  RunContext& run_;
  const Method& method_;
  std::int64_t every_ = 1, last_row_step_ = -1;
  ThermoTable table_;
  io::CsvWriter csv_;
};

}  // namespace shockfield
