#include "shockfield/materials/eos/mie_gruneisen.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

void MieGruneisen::validate(const std::string& where) const {
  auto require = [&](bool ok, const char* name, const char* expected, double value) {
    if (!ok) throw InputError(fmt::format("{}: Mie-Grüneisen {} = {} (expected {})", where, name, value, expected));
  };
  require(rho0 > 0.0 && std::isfinite(rho0), "rho0", "a positive density in kg/m³", rho0);
  require(c0 > 0.0 && std::isfinite(c0), "c0", "a positive sound speed in m/s", c0);
  require(lambda >= 0.0 && std::isfinite(lambda), "lambda", "a Us-Up slope >= 0", lambda);
  require(gamma0 >= 0.0 && std::isfinite(gamma0), "gamma0", "a Grüneisen coefficient >= 0", gamma0);
}

double MieGruneisen::compression(double rho) const {
  const double eta = 1.0 - rho0 / rho;
  if (!(rho > 0.0) || (lambda > 0.0 && lambda * eta >= 1.0))
    throw RunError(fmt::format("Mie-Grüneisen: density {} kg/m³ is beyond the Hugoniot limit ρ0·λ/(λ−1) "
                               "(ρ0 = {}, λ = {})", rho, rho0, lambda));
  return eta;
}

double MieGruneisen::hugoniot_pressure(double rho) const {
  const double eta = compression(rho);
  if (eta <= 0.0) return bulk_modulus() * eta;  // eq. 6, tension branch
  const double d = 1.0 - lambda * eta;
  return bulk_modulus() * eta / (d * d);  // eq. 6, compression branch
}

double MieGruneisen::hugoniot_energy(double rho) const {
  const double eta = 1.0 - rho0 / rho;  // V0 − V = η/ρ0
  return 0.5 * hugoniot_pressure(rho) * eta / rho0;
}

double MieGruneisen::pressure(double rho, double e) const {
  return hugoniot_pressure(rho) + energy_coefficient() * (e - hugoniot_energy(rho));  // eq. 5
}

double MieGruneisen::sound_speed(double rho, double e) const {
  const double eta = compression(rho);
  const double k0 = bulk_modulus();
  // dP_H/dη and dE_H/dη = (P_H + η·dP_H/dη)/(2ρ0); dη/dρ = ρ0/ρ².
  double ph = k0 * eta, dph = k0;
  if (eta > 0.0) {
    const double d = 1.0 - lambda * eta;
    ph = k0 * eta / (d * d);
    dph = k0 * (1.0 + lambda * eta) / (d * d * d);
  }
  const double deh = (ph + eta * dph) / (2.0 * rho0);
  const double dp_drho_e = (dph - energy_coefficient() * deh) * rho0 / (rho * rho);
  const double p = ph + energy_coefficient() * (e - 0.5 * ph * eta / rho0);
  const double c2 = dp_drho_e + p / (rho * rho) * energy_coefficient();
  // Deep tension with a large energy term can make c² tiny or negative; the bulk speed at ρ0
  // bounds the stable step from below in that case.
  return std::sqrt(std::max(c2, 1e-6 * c0 * c0));
}

}  // namespace shockfield::materials
