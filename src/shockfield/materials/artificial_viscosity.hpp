#pragma once
// Bulk artificial viscosity (von Neumann & Richtmyer 1950, linear term of Landshoff 1955), added
// to the pressure of a compressing point so that shocks spread over a few cells instead of
// ringing:
//   q = ρ·ℓ·(C_Q·ℓ·(∇·v)² − C_L·c·∇·v)   for ∇·v < 0,   q = 0 otherwise,
// with ℓ the cell size and c the sound speed. Defaults C_Q = 2.0, C_L = 1.0 are ours. C_Q was set on
// the aluminium of Xu et al. (2015) 1000 m/s symmetric impact (tests/unit/mpm/test_aluminium_impact.cpp): the
// finite element defaults of LS-DYNA's *CONTROL_BULK_VISCOSITY (Q1 = 1.5, Q2 = 0.06) leave enough
// ringing behind an MPM shock (±8% stress) that the overshoot raises the eq.-7 temperature rise by
// ~20%. C_L was 0.3 until the ringing it leaves was found to cycle every point of a strong metal
// through reverse yield and erase its deviatoric stress (copper at ±500/±1000 m/s: von Mises
// 0.23/0.26 of yield with C_L = 0.3, 0.96/0.95 with 0.5, 0.98/1.00 with 1.0; docs/theory/mpm.md,
// "Deviatoric stress behind shocks"); C_L ≥ 0.5 also removes the density overshoot of "Shock
// temperature" there.
#include <string>

namespace shockfield::materials {

struct ArtificialViscosity {
  double quadratic = 2.0;  ///< C_Q [-]
  double linear = 1.0;    ///< C_L [-]

  void validate(const std::string& where) const;
  /// The evaluation function: q [Pa] for density ρ, sound speed c, velocity divergence div_v
  /// [1/s] and length ℓ [m].
  double pressure(double rho, double sound_speed, double div_v, double length) const {
    if (div_v >= 0.0) return 0.0;
    return rho * length * (quadratic * length * div_v * div_v - linear * sound_speed * div_v);
  }
};

}  // namespace shockfield::materials
