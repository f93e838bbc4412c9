#pragma once
// Mie-Grüneisen equation of state referenced to the linear Us-Up shock Hugoniot (Xu et al. 2015, // §2.2.1, eqs. 5-6). SI units: density kg/m³, specific internal energy J/kg, pressure Pa.
//
//   P(ρ, e) = P_H(V) + (γ/V)·[e − E_H(V)],   γ/V = ργ = ρ0γ0            (eq. 5)
//   P_H = ρ0c0²η / (1 − λη)²  for V ≤ V0 (η = 1 − V/V0 ≥ 0)              (eq. 6, compression)
//   P_H = ρ0c0²η              for V > V0 (tension, η < 0)                (eq. 6, tension)
//   E_H = ½·P_H·(V0 − V)      (Rankine-Hugoniot energy jump from P = 0, e = 0)
//
// The reference state (ρ0, e = 0) has zero pressure. Eq. 6 as printed in the paper reads
// ρ0c0²(V/V0 − 1) on the tension branch, which would make stretched material push outwards;
// we use the sign that continues the compression branch with the same slope (the printed sign
// is a typo: the compression branch tends to ρ0c0²(1 − V/V0) as V → V0).
#include <string>

namespace shockfield::materials {

struct MieGruneisen {
  double rho0 = 0.0;    ///< reference density ρ0 [kg/m³]
  double c0 = 0.0;      ///< bulk sound speed, intercept of Us = c0 + λ·Up [m/s]
  double lambda = 0.0;  ///< slope λ of Us = c0 + λ·Up [-]
  double gamma0 = 0.0;  ///< Grüneisen coefficient at ρ0; ργ = ρ0γ0 [-]

  /// Throws InputError naming the parameter when a value is out of range; `where` prefixes it.
  void validate(const std::string& where) const;

  /// The evaluation function: pressure P(ρ, e) of eq. 5 [Pa]. RunError beyond the Hugoniot
  /// singularity η = 1/λ.
  double pressure(double rho, double e) const;

  /// The Hugoniot at one density, evaluated once and shared by the pressure, energy and sound
  /// speed of a material-point update.
  struct HugoniotPoint {
    double rho = 0.0;  ///< ρ [kg/m³]
    double eta = 0.0;  ///< η = 1 − ρ0/ρ
    double ph = 0.0;   ///< P_H (eq. 6) [Pa]
    double dph = 0.0;  ///< dP_H/dη [Pa]
    double eh = 0.0;   ///< E_H = ½P_H(V0 − V) [J/kg]
  };
  /// RunError beyond the Hugoniot singularity η = 1/λ. (Inline: it runs once per point update.)
  HugoniotPoint hugoniot(double rho) const {
    HugoniotPoint h;
    h.rho = rho;
    h.eta = compression(rho);
    const double k0 = bulk_modulus();
    h.ph = k0 * h.eta, h.dph = k0;  // eq. 6, tension branch
    if (h.eta > 0.0) {              // eq. 6, compression branch
      const double inv_d = 1.0 / (1.0 - lambda * h.eta), inv_d2 = inv_d * inv_d;
      h.ph = k0 * h.eta * inv_d2;
      h.dph = k0 * (1.0 + lambda * h.eta) * inv_d2 * inv_d;
    }
    h.eh = 0.5 * h.ph * h.eta / rho0;  // V0 − V = η/ρ0
    return h;
  }
  /// Squared isentropic bulk sound speed at the Hugoniot point's density and energy e, floored
  /// at 10⁻⁶c0² [m²/s²].
  double sound_speed_squared(const HugoniotPoint& h, double e) const {
    // dE_H/dη = (P_H + η·dP_H/dη)/(2ρ0); dη/dρ = ρ0/ρ².
    const double deh = (h.ph + h.eta * h.dph) / (2.0 * rho0);
    const double inv_rho2 = 1.0 / (h.rho * h.rho);
    const double dp_drho_e = (h.dph - energy_coefficient() * deh) * rho0 * inv_rho2;
    const double p = h.ph + energy_coefficient() * (e - h.eh);
    const double c2 = dp_drho_e + p * inv_rho2 * energy_coefficient();
    // Deep tension with a large energy term can make c² tiny or negative; the bulk speed at ρ0
    // bounds the stable step from below in that case.
    return c2 > 1e-6 * c0 * c0 ? c2 : 1e-6 * c0 * c0;
  }

  /// Hugoniot pressure P_H(ρ) (eq. 6) [Pa].
  double hugoniot_pressure(double rho) const;
  /// Hugoniot specific energy E_H(ρ) = ½P_H(V0 − V) [J/kg].
  double hugoniot_energy(double rho) const;
  /// ∂P/∂e at fixed ρ: γ/V = ρ0γ0 [kg/m³].
  double energy_coefficient() const { return rho0 * gamma0; }
  /// Isentropic bulk sound speed c = √(∂P/∂ρ|_e + P/ρ²·∂P/∂e|_ρ) [m/s].
  double sound_speed(double rho, double e) const;
  /// Shock speed of the linear Hugoniot Us = c0 + λ·Up [m/s].
  double shock_speed(double up) const { return c0 + lambda * up; }
  /// Bulk modulus at the reference state ρ0c0² [Pa].
  double bulk_modulus() const { return rho0 * c0 * c0; }

 private:
  double compression(double rho) const {  // η = 1 − ρ0/ρ, checked against 1/λ
    const double eta = 1.0 - rho0 / rho;
    if (!(rho > 0.0) || (lambda > 0.0 && lambda * eta >= 1.0)) beyond_limit(rho);
    return eta;
  }
  [[noreturn]] void beyond_limit(double rho) const;
};

}  // namespace shockfield::materials
