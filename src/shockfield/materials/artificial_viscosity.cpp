#include "shockfield/materials/artificial_viscosity.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

void ArtificialViscosity::validate(const std::string& where) const {
  if (!(quadratic >= 0.0 && std::isfinite(quadratic)))
    throw InputError(fmt::format("{}: artificial viscosity quadratic = {} (expected >= 0)", where, quadratic));
  if (!(linear >= 0.0 && std::isfinite(linear)))
    throw InputError(fmt::format("{}: artificial viscosity linear = {} (expected >= 0)", where, linear));
}

}  // namespace shockfield::materials
