#pragma once
// Nesterenko's solitary wave of a Hertzian chain without precompression, from the long-wave
// (continuum) approximation of identical grains of mass m and diameter a with F = κ δ^{3/2}
// (V. F. Nesterenko, J. Appl. Mech. Tech. Phys. 24, 733 (1983); Dynamics of Heterogeneous
// Materials, Springer 2001, §1.2; derivation in docs/theory/granular.md):
//   c² = κ a^{5/2}/m,
//   strain ξ(s) = ξ_m cos⁴(√10 s/(5a)) for |√10 s/(5a)| ≤ π/2 (s = x − V_s t), 0 outside,
//   V_s² = (4/5) c² ξ_m^{1/2},  grain velocity v = V_s ξ,  so
//   V_s = (16/25)^{1/5} c^{4/5} v_m^{1/5}.
// The wave's support is 5π/√10 ≈ 4.97 grain diameters.
#include <cmath>
#include <numbers>

namespace shockfield::granular {

struct NesterenkoWave {
  double kappa = 0.0;     ///< κ [N/m^{3/2}]
  double mass = 0.0;      ///< m [kg]
  double diameter = 0.0;  ///< a [m]

  /// c [m/s] of the long-wave equation.
  double c() const { return std::sqrt(kappa * std::pow(diameter, 2.5) / mass); }
  /// V_s [m/s] for a peak grain velocity v_m [m/s].
  double speed(double v_max) const {
    return std::pow(16.0 / 25.0, 0.2) * std::pow(c(), 0.8) * std::pow(v_max, 0.2);
  }
  /// v/v_m at distance s [m] from the peak.
  double velocity_shape(double s) const {
    const double phase = std::sqrt(10.0) * s / (5.0 * diameter);
    if (std::abs(phase) >= std::numbers::pi / 2) return 0.0;
    const double cs = std::cos(phase);
    return cs * cs * cs * cs;
  }
  /// Full width of the support in diameters, 5π/√10.
  static double support_width() { return 5.0 * std::numbers::pi / std::sqrt(10.0); }
  /// Full width of the velocity profile where v > fraction·v_m, in diameters:
  /// 2·(5/√10)·arccos(fraction^{1/4}).
  static double width_above(double fraction) {
    return 10.0 / std::sqrt(10.0) * std::acos(std::pow(fraction, 0.25));
  }
  /// Full width at half maximum of the velocity (and strain) profile in diameters,
  /// 2·(5/√10)·arccos(2^{-1/4}).
  static double velocity_fwhm() { return width_above(0.5); }
};

}  // namespace shockfield::granular
