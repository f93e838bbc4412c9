#include "shockfield/materials/eos/carnahan_starling.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/eos/van_der_waals.hpp"

namespace shockfield::materials {

void CarnahanStarling::validate(const std::string& where) const {
  if (!(a > 0.0))
    throw InputError(fmt::format("{}: Carnahan-Starling a = {} must be > 0", where, a));
  if (!(b > 0.0))
    throw InputError(fmt::format("{}: Carnahan-Starling b = {} must be > 0", where, b));
}

double CarnahanStarling::pressure(double rho, double T) const {
  check_reduced_state(rho, T, max_density(), "Carnahan-Starling");
  const double eta = b * rho / 4.0, s = 1.0 - eta;
  return rho * T * (1.0 + eta + eta * eta - eta * eta * eta) / (s * s * s) - a * rho * rho;  // eq. 19
}

double CarnahanStarling::dpressure_drho(double rho, double T) const {
  check_reduced_state(rho, T, max_density(), "Carnahan-Starling");
  // d/dρ [ρ Z(η)] with Z = (1 + η + η² − η³)/(1 − η)³ equals (1 + 4η + 4η² − 4η³ + η⁴)/(1 − η)⁴.
  const double eta = b * rho / 4.0, s = 1.0 - eta;
  const double e2 = eta * eta;
  return T * (1.0 + 4.0 * eta + 4.0 * e2 - 4.0 * e2 * eta + e2 * e2) / (s * s * s * s) -
         2.0 * a * rho;
}

}  // namespace shockfield::materials
