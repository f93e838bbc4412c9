#pragma once
// Van der Waals equation of state in the reduced units of the GLS discrete Boltzmann model
// (Xu et al. 2015, §2.3.2): P = ρT/(1 − bρ) − aρ²; with the paper's a = 9/8, b = 1/3 this is
// P = 3ρT/(3 − ρ) − 9ρ²/8, whose critical point is ρ_c = T_c = 1, P_c = 3/8.
#include <string>

namespace shockfield::materials {

struct VanDerWaals {
  double a = 9.0 / 8.0;  ///< attraction
  double b = 1.0 / 3.0;  ///< excluded volume: densities must stay below 1/b

  /// InputError naming the parameter when a or b is not positive; `where` prefixes it.
  void validate(const std::string& where) const;
  /// The evaluation function; RunError for ρ outside (0, 1/b) or T ≤ 0.
  double pressure(double rho, double T) const;
  double dpressure_drho(double rho, double T) const;
  double max_density() const { return 1.0 / b; }
  /// Critical point: ρ_c = 1/(3b), T_c = 8a/(27b), P_c = a/(27b²).
  double critical_density() const { return 1.0 / (3.0 * b); }
  double critical_temperature() const { return 8.0 * a / (27.0 * b); }
};

/// RunError unless 0 < ρ < max_density and T > 0 (shared by the reduced-unit liquid–vapour
/// equations of state, van der Waals and Carnahan–Starling).
void check_reduced_state(double rho, double T, double max_density, const char* eos);

}  // namespace shockfield::materials
