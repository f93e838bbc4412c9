#include "shockfield/materials/thermal.hpp"

#include <algorithm>
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

double Thermal::hugoniot_slope(const MieGruneisen& eos, double v, double temperature) const {
  const double v0 = 1.0 / eos.rho0;
  const double l = eos.lambda;
  const double d = (l - 1.0) * v0 - l * v;
  const double shock = eos.c0 * eos.c0 * l * (v0 - v) * (v0 - v) / (heat_capacity * d * d * d);
  return shock - eos.energy_coefficient() * temperature;  // eq. 7, γ/V = ρ0γ0
}

double Thermal::advance(const MieGruneisen& eos, double v_old, double v_new, double temperature, double dwp,
                        double& shock_volume) const {
  auto isentrope = [&](double, double t) { return -eos.energy_coefficient() * t; };
  auto hugoniot = [&](double v, double t) { return hugoniot_slope(eos, v, t); };
  auto rk2 = [](double va, double vb, double t, auto slope) {
    const double dv = vb - va;
    return t + dv * slope(va + 0.5 * dv, t + 0.5 * dv * slope(va, t));
  };
  double t = temperature;
  if (v_new < shock_volume) {  // a new, stronger shock state: isentrope down to it, then eq. 7
    const double v_shock_start = std::min(v_old, shock_volume);
    t = rk2(v_old, v_shock_start, t, isentrope);
    t = rk2(v_shock_start, v_new, t, hugoniot);
    shock_volume = v_new;
  } else {
    t = rk2(v_old, v_new, t, isentrope);
  }
  return t + dwp / heat_capacity;  // eq. 8
}

}  // namespace shockfield::materials
