#include "shockfield/materials/eos/van_der_waals.hpp"

#include <cmath>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {
void check_reduced_state(double rho, double T, double max_density, const char* eos) {
  if (!(rho > 0.0 && rho < max_density) || !(T > 0.0))
    throw RunError(fmt::format(
        "{} equation of state: density {} must be in (0, {:.6g}) and temperature {} positive "
        "(the liquid is compressed beyond its excluded volume, or the state broke down)",
        eos, rho, max_density, T));
}

void VanDerWaals::validate(const std::string& where) const {
  if (!(a > 0.0)) throw InputError(fmt::format("{}: van der Waals a = {} must be > 0", where, a));
  if (!(b > 0.0)) throw InputError(fmt::format("{}: van der Waals b = {} must be > 0", where, b));
}

double VanDerWaals::pressure(double rho, double T) const {
  check_reduced_state(rho, T, max_density(), "van der Waals");
  return rho * T / (1.0 - b * rho) - a * rho * rho;
}

double VanDerWaals::dpressure_drho(double rho, double T) const {
  check_reduced_state(rho, T, max_density(), "van der Waals");
  const double s = 1.0 - b * rho;
  return T / (s * s) - 2.0 * a * rho;
}

}  // namespace shockfield::materials
