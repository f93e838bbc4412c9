#include "shockfield/materials/eos/mie_gruneisen.hpp"

#include <algorithm>
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

MieGruneisen::HugoniotPoint MieGruneisen::hugoniot(double rho) const {
  HugoniotPoint h;
  h.rho = rho;
  h.eta = compression(rho);
  const double k0 = bulk_modulus();
  h.ph = k0 * h.eta, h.dph = k0;  // eq. 6, tension branch
  if (h.eta > 0.0) {              // eq. 6, compression branch
    const double d = 1.0 - lambda * h.eta;
    h.ph = k0 * h.eta / (d * d);
    h.dph = k0 * (1.0 + lambda * h.eta) / (d * d * d);
  }
  h.eh = 0.5 * h.ph * h.eta / rho0;  // V0 − V = η/ρ0
  return h;
}

double MieGruneisen::hugoniot_pressure(double rho) const { return hugoniot(rho).ph; }

double MieGruneisen::hugoniot_energy(double rho) const { return hugoniot(rho).eh; }

double MieGruneisen::pressure(double rho, double e) const {
  const HugoniotPoint h = hugoniot(rho);
  return h.ph + energy_coefficient() * (e - h.eh);  // eq. 5
}

double MieGruneisen::sound_speed_squared(const HugoniotPoint& h, double e) const {
  // dE_H/dη = (P_H + η·dP_H/dη)/(2ρ0); dη/dρ = ρ0/ρ².
  const double deh = (h.ph + h.eta * h.dph) / (2.0 * rho0);
  const double inv_rho2 = 1.0 / (h.rho * h.rho);
  const double dp_drho_e = (h.dph - energy_coefficient() * deh) * rho0 * inv_rho2;
  const double p = h.ph + energy_coefficient() * (e - h.eh);
  const double c2 = dp_drho_e + p * inv_rho2 * energy_coefficient();
  // Deep tension with a large energy term can make c² tiny or negative; the bulk speed at ρ0
  // bounds the stable step from below in that case.
  return std::max(c2, 1e-6 * c0 * c0);
}

double MieGruneisen::sound_speed(double rho, double e) const { return std::sqrt(sound_speed_squared(hugoniot(rho), e)); }

}  // namespace shockfield::materials
