#pragma once
// The well-posed Ginzburg–Landau (Allen–Cahn) model of phase-domain growth built on Xu et al.
// (2015) §4.4.3 (docs/theory/phasefield.md): ∂ₜξ = −f′(ξ) + D∇²ξ with the double well of their
// eq 38, f(ξ) = a/2 ξ² − (a+1)/3 ξ³ + ξ⁴/4 (ξ = 0 bcc, 1 hcp), and its closed forms.
#include <array>
#include <cmath>

namespace shockfield::phasefield {

struct Model {
  double a = 0.5;  ///< bulk parameter: a < 1/2 hcp stable, a > 1/2 bcc stable (eq 38)
  double D = 1.0;  ///< gradient coefficient (length²/time), > 0
  /// Anisotropic gradient energy: D_d = D · anisotropy[d] along axis d, F = ∫ [f + Σ_d D_d/2 (∂_d ξ)²].
  /// A flat front normal to axis d moves at √(D_d/2)(1 − 2a); growth shapes become ellipsoids with
  /// axes ∝ √D_d. The closed forms below are those of the isotropic model (all 1).
  std::array<double, 3> anisotropy{1.0, 1.0, 1.0};

  /// The gradient coefficient along axis d.
  double D_along(int d) const { return D * anisotropy[d]; }

  /// f(ξ), eq 38.
  double f(double xi) const { return xi * xi * (0.5 * a - (a + 1.0) / 3.0 * xi + 0.25 * xi * xi); }
  /// f′(ξ) = ξ(ξ − a)(ξ − 1).
  double df(double xi) const { return xi * (xi - a) * (xi - 1.0); }
  /// Growth speed of the hcp phase at a flat front (Nagumo wave): c₀ = √(D/2)(1 − 2a).
  double front_speed() const { return std::sqrt(0.5 * D) * (1.0 - 2.0 * a); }
  /// Logistic length of the front profile, √(2D).
  double front_length() const { return std::sqrt(2.0 * D); }
  /// The flat-front profile at signed distance d from the ξ = 1/2 level, d > 0 on the bcc side:
  /// ξ = [1 − tanh(d / (2√(2D)))]/2.
  double profile(double d) const { return 0.5 * (1.0 - std::tanh(d / (2.0 * front_length()))); }
  /// Critical radius of an hcp domain in `dim` dimensions, R* = (dim − 1)D/c₀ (infinite for
  /// a ≥ 1/2): Ṙ = c₀ − (dim − 1)D/R.
  double critical_radius(int dim) const {
    const double c0 = front_speed();
    return c0 > 0.0 ? (dim - 1) * D / c0 : INFINITY;
  }
};

}  // namespace shockfield::phasefield
