#pragma once
// The sharp-interface growth law of the well-posed phase-field model (docs/theory/phasefield.md,
// "The curvature correction") fitted to a measured domain radius R(t):
//
//   Ṙ = c₀ − (n − 1) D / R,
//
// v = c₀ − Dκ for a sphere (n = 3, κ = 2/R) or a disc (n = 2). In the sign convention of Xu et al.
// (2015) eq 43, v = c₀ + Dk, the same D holds with k = −κ (curvature counted positive for a
// concave hcp domain). Fitted by non-linear least squares (Gauss–Newton with Levenberg–Marquardt
// damping) of the integrated law, parameters (R₀, c₀, D), R₀ the radius at the first point; the
// model R(t_i) and its sensitivities ∂R/∂(R₀, c₀, D) are integrated with RK4 between the
// points. Covariance C = s²(JᵀJ)⁻¹ with s² = χ²/(m − 3) (Press et al. (2007) §15.4, §15.5).
#include <string>
#include <vector>

namespace shockfield::phasefield {

struct GrowthFit {
  double R0 = 0, c0 = 0, D = 0;                        ///< radius at t[0], front speed, curvature coefficient
  double R0_stderr = 0, c0_stderr = 0, D_stderr = 0;   ///< standard errors
  double c0_D_covariance = 0;
  double residual_rms = 0;  ///< √(χ²/m)
  int points = 0, iterations = 0;
  bool converged = false;
  /// The first-guess slope fit, ΔR/Δt = c₀ − (n − 1)D ⟨1/R⟩ over each interval (trapezoidal ⟨1/R⟩).
  double c0_differences = 0, D_differences = 0;
};

/// The radius of the law at the times `t` from R(t[0]) = R0 (RK4, 64 substeps per interval, which
/// stops at R → 0: a domain that vanishes has R = 0 afterwards).
std::vector<double> growth_law_radius(const std::vector<double>& t, double R0, double c0, double D, int dimensions);

/// Fits R(t) (t increasing, R > 0, at least 4 points; InputError otherwise, naming `what`).
GrowthFit fit_growth_law(const std::vector<double>& t, const std::vector<double>& R, int dimensions,
                         const std::string& what);

}  // namespace shockfield::phasefield
