#include "shockfield/core/run_thermo.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace shockfield {

RunThermo::RunThermo(RunContext& run, const Method& method) : run_(run), method_(method) {
  every_ = std::max<std::int64_t>(1, method.thermo_every());
  const std::vector<std::string> columns = method.thermo_columns();
  if (!method.writes_thermo_csv()) {
    const double keep = static_cast<double>(method.step());
    csv_ = io::CsvWriter(run.folder / "thermo.csv", columns, run.options.resume ? &keep : nullptr);
  }
  std::string header;
  for (const std::string& c : columns) {
    widths_.push_back(std::max<std::size_t>(c.size(), 12));
    header += fmt::format(" {:>{}}", c, widths_.back());
  }
  run.log.line(header);
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
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) text += fmt::format(" {:>{}.8g}", values[i], widths_[i]);
  run_.log.line(text);
  if (csv_.is_open()) csv_.row(values);
}

}  // namespace shockfield
