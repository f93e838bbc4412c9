#include "shockfield/core/thermo_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shockfield {
namespace {

// Wide enough for any %.8g value: sign, 8 digits, the point and a three-digit exponent
// ("-1.2345678e-100" is 15 characters).
constexpr std::size_t kMinWidth = 15;

std::string format_value(double v) {
  if (std::isfinite(v) && v == std::trunc(v) && std::fabs(v) < 1e15)
    return fmt::format("{}", static_cast<long long>(v));
  if (std::isnan(v)) return "nan";
  return fmt::format("{:.8g}", v);
}

}  // namespace

ThermoTable::ThermoTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  for (const auto& name : columns_) {
    if (name.empty() || name.find_first_of(" \t\n") != std::string::npos)
      throw std::invalid_argument(fmt::format("thermo column name '{}' is empty or has spaces", name));
    widths_.push_back(std::max(kMinWidth, name.size()));
  }
}

std::string ThermoTable::header() const {
  std::string out;
  for (std::size_t c = 0; c < columns_.size(); ++c)
    out += fmt::format("{}{:>{}}", c ? " " : "", columns_[c], widths_[c]);
  return out;
}

std::string ThermoTable::row(const std::vector<double>& values) const {
  if (values.size() != columns_.size())
    throw std::invalid_argument(fmt::format("thermo row has {} values for {} columns", values.size(),
                                            columns_.size()));
  std::string out;
  for (std::size_t c = 0; c < values.size(); ++c)
    out += fmt::format("{}{:>{}}", c ? " " : "", format_value(values[c]), widths_[c]);
  return out;
}

}  // namespace shockfield
