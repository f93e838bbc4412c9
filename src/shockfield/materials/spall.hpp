#pragma once
// Tensile (spall) failure of a material point: the instantaneous spall-strength criterion with a
// damage variable (the "hydrodynamic tensile limit" of hydrocodes; Antoun, Seaman, Curran,
// Kanel, Razorenov & Utkin, "Spall Fracture", Springer 2003, §1.3 and §2.2; Wilkins,
// "Computer Simulation of Dynamic Phenomena", Springer 1999, ch. 8). Xu et al. (2015) §4.2.2: the
// rarefactions that meet inside a shocked body open new cavities.
//
//   D: 0 → 1  once the mean stress tr σ/3 = −(P + q) falls below −σ_spall
//   D = 1:    s = 0 (no shear strength) and P = max(P_EOS, 0) (no tension; compression is carried,
//             so a spall plane can close again)
//
// A failed point keeps its energy balance: when its tension is cut, the energy update uses the
// clipped pressure in place of the EOS one (see apply()).
//
// Rate-dependent alternative (tuler_butcher_exponent λ > 0): the Tuler–Butcher cumulative damage
// criterion (Tuler & Butcher, Int. J. Fract. Mech. 4 (1968) 431),
//   ∫ (σ_t − σ_0)^λ dt = K_f   over the time the tensile mean stress σ_t = −(P + q) exceeds σ_0,
// with σ_0 = `strength` the threshold below which no damage accumulates. The point carries
// D = (1/K_f) ∫ (σ_t − σ_0)^λ dt in [0, 1) (no softening before failure) and fails (D = 1) when
// the integral reaches K_f: a short tensile pulse must exceed σ_0 by more, so the spall stress
// rises with the loading rate; K_f → 0 is the instantaneous criterion. The free-surface
// pull-back it produces is the classical spall measurement, σ_spall ≈ ½·ρ0·c0·Δu_fs (acoustic
// approximation; Antoun et al. §2.2, eq. 2.2).
#include <string>

#include "shockfield/core/types.hpp"

namespace shockfield::materials {

struct PointState;

struct SpallFailure {
  double strength = 0.0;  ///< σ_spall [Pa] (σ_0 with Tuler–Butcher); 0 switches the model off
  double tuler_butcher_exponent = 0.0;  ///< λ; 0: the instantaneous criterion
  double tuler_butcher_integral = 0.0;  ///< K_f [Pa^λ·s], > 0 when λ > 0

  bool enabled() const { return strength > 0.0; }
  void validate(const std::string& where) const;
  /// Applies the criterion to a point just updated by SolidMaterial::update, whose energy came
  /// from the trapezoidal rule over the step: −½(P_old + P + 2q)·dv + v̄·½(s_old + s):Δe, with dv
  /// the change of specific volume, v̄ its mean and Δe the deviatoric strain increment. Cutting
  /// P to 0 and s to 0 at the end of the step means the trapezoid should have used 0 there: e
  /// gains ½·P·dv (exact, as P = a + b·e is linear in e) and loses v̄·½·s:Δe.
  /// `dt` is the step (the Tuler–Butcher integral advances by (σ_t − σ_0)^λ·dt at the step's end).
  void apply(PointState& p, double dv, double v_mean, const Mat3& de, double dt) const;
};

}  // namespace shockfield::materials
