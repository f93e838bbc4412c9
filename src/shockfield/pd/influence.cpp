#include "shockfield/pd/influence.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {

const std::vector<std::string>& Influence::names() {
  static const std::vector<std::string> table{"constant", "inverse", "conical", "gaussian"};
  return table;
}

Influence Influence::from_name(const std::string& name) {
  const auto& table = names();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i] == name) return Influence(static_cast<Kind>(i));
  throw InputError(fmt::format("unknown influence function '{}' (expected one of {})", name, fmt::join(table, ", ")));
}

double Influence::operator()(double r, double horizon) const {
  switch (kind_) {
    case Kind::constant: return 1.0;
    case Kind::inverse: return 1.0 / r;
    case Kind::conical: return 1.0 - r / horizon;
    case Kind::gaussian: return std::exp(-(r * r) / (horizon * horizon));
  }
  return 1.0;
}

}  // namespace shockfield::pd
