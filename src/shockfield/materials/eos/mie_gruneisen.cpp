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

void MieGruneisen::beyond_limit(double rho) const {
  throw RunError(fmt::format("Mie-Grüneisen: density {} kg/m³ is beyond the Hugoniot limit ρ0·λ/(λ−1) "
                             "(ρ0 = {}, λ = {})", rho, rho0, lambda));
}

double MieGruneisen::hugoniot_pressure(double rho) const { return hugoniot(rho).ph; }

double MieGruneisen::hugoniot_energy(double rho) const { return hugoniot(rho).eh; }

double MieGruneisen::pressure(double rho, double e) const {
  const HugoniotPoint h = hugoniot(rho);
  return h.ph + energy_coefficient() * (e - h.eh);  // eq. 5
}

double MieGruneisen::sound_speed(double rho, double e) const { return std::sqrt(sound_speed_squared(hugoniot(rho), e)); }

}  // namespace shockfield::materials
