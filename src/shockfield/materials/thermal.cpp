#include "shockfield/materials/thermal.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

void Thermal::validate(const std::string& where) const {
  auto require = [&](bool ok, const char* name, const char* expected, double value) {
    if (!ok) throw InputError(fmt::format("{}: thermal {} = {} (expected {})", where, name, value, expected));
  };
  require(heat_capacity > 0.0 && std::isfinite(heat_capacity), "heat_capacity", "> 0 J/(kg·K)", heat_capacity);
  require(conductivity >= 0.0, "conductivity", ">= 0 W/(m·K)", conductivity);
  require(initial_temperature > 0.0, "initial_temperature", "> 0 K", initial_temperature);
}

}  // namespace shockfield::materials
