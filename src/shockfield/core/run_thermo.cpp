#include "shockfield/core/run_thermo.hpp"

#include <algorithm>

namespace shockfield {

RunThermo::RunThermo(RunContext& run, const Method& method)
    : run_(run), method_(method), table_(method.thermo_columns()) {
  every_ = std::max<std::int64_t>(1, method.thermo_every());
  if (!method.writes_thermo_csv()) {
    const double keep = static_cast<double>(method.step());
    csv_ = io::CsvWriter(run.folder / "thermo.csv", table_.columns(), run.options.resume ? &keep : nullptr);
  }
  run.log.line(table_.header());
  if (run.options.resume) last_row_step_ = method.step();
  else row();
}

void RunThermo::at_step() {
  if (method_.step() % every_ == 0) row();
}

void RunThermo::at_end() {
  if (method_.step() != last_row_step_) row();
}

void RunThermo::row() {
  last_row_step_ = method_.step();
  const std::vector<double> values = method_.thermo_values();
  run_.log.line(table_.row(values));
  if (csv_.is_open()) csv_.row(values);
}

}  // namespace shockfield
