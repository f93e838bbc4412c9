#pragma once
// Temperature of a material point (Xu et al. 2015, §2.2.1): heating by shock compression along the
// Hugoniot (eq. 7) and by plastic work (eq. 8), in increments as the paper suggests.
//
//   dT_H/dV = c0²λ(V0 − V)² / (c_v[(λ−1)V0 − λV]³) − (γ/V)·T          (eq. 7)
//   dT_p    = dW_p / c_v                                                (eq. 8)
//
// with γ/V = ρ0γ0 (ργ = ρ0γ0). Eq. 7 is applied while a point is compressed beyond the smallest
// specific volume it has reached so far (its "shock volume": a new, stronger shock state).
// Otherwise only the isentropic part −(γ/V)T is kept: release from a shocked state follows the
// isentrope, not the Hugoniot, so the entropy a shock deposited is not taken back, and the
// ringing behind a numerical shock front does not pump heat in. Heat conduction with the
// conductivity k is solved between points by the MPM when switched on (mpm/heat_conduction.hpp,
// [solver] heat_conduction); it is off by default: over the ns-µs times of the paper's MPM studies
// it is negligible ("The thermal process is much slower", §4.2.2).
#include <string>

#include "shockfield/materials/eos/mie_gruneisen.hpp"

namespace shockfield::materials {

struct Thermal {
  double heat_capacity = 0.0;        ///< c_v [J/(kg·K)]
  double conductivity = 0.0;         ///< k [W/(m·K)], used by mpm::HeatConduction only
  double initial_temperature = 300;  ///< T0 [K]

  void validate(const std::string& where) const;
  /// dT/dV along the Hugoniot of `eos` at specific volume v and temperature T (eq. 7) [K·kg/m³].
  double hugoniot_slope(const MieGruneisen& eos, double v, double temperature) const {
    const double v0 = 1.0 / eos.rho0;
    const double l = eos.lambda;
    const double d = (l - 1.0) * v0 - l * v;
    const double shock = eos.c0 * eos.c0 * l * (v0 - v) * (v0 - v) / (heat_capacity * d * d * d);
    return shock - eos.energy_coefficient() * temperature;  // eq. 7, γ/V = ρ0γ0
  }
  /// The evaluation function: temperature after the specific volume changes from v_old to v_new
  /// and the specific plastic work grows by dwp [J/kg] (eqs. 7-8, second-order Runge-Kutta in V).
  /// `shock_volume` is the smallest specific volume reached so far; it is updated.
  /// (Inline: it runs once per material-point update.)
  double advance(const MieGruneisen& eos, double v_old, double v_new, double temperature, double dwp,
                 double& shock_volume) const {
    auto isentrope = [&](double, double t) { return -eos.energy_coefficient() * t; };
    auto hugoniot = [&](double v, double t) { return hugoniot_slope(eos, v, t); };
    auto rk2 = [](double va, double vb, double t, auto slope) {
      const double dv = vb - va;
      return t + dv * slope(va + 0.5 * dv, t + 0.5 * dv * slope(va, t));
    };
    double t = temperature;
    if (v_new < shock_volume) {  // a new, stronger shock state: isentrope down to it, then eq. 7
      const double v_shock_start = v_old < shock_volume ? v_old : shock_volume;
      t = rk2(v_old, v_shock_start, t, isentrope);
      t = rk2(v_shock_start, v_new, t, hugoniot);
      shock_volume = v_new;
    } else {
      t = rk2(v_old, v_new, t, isentrope);
    }
    return dwp != 0.0 ? t + dwp / heat_capacity : t;  // eq. 8 (no division for an elastic step)
  }
};

}  // namespace shockfield::materials
