#pragma once
// Carnahan–Starling equation of state, Xu et al. (2015) eq. 19, in the reduced units of the GLS discrete
// Boltzmann model: P = ρT(1 + η + η² − η³)/(1 − η)³ − aρ², η = bρ/4. Its critical point has no
// closed form; dbm/coexistence.hpp finds it numerically.
#include <string>

namespace shockfield::materials {

struct CarnahanStarling {
  double a = 1.0;  ///< attraction
  double b = 1.0;  ///< repulsion (hard-sphere volume): packing fraction η = bρ/4 < 1

  void validate(const std::string& where) const;
  /// The evaluation function; RunError for ρ outside (0, 4/b) or T ≤ 0.
  double pressure(double rho, double T) const;
  double dpressure_drho(double rho, double T) const;
  double max_density() const { return 4.0 / b; }
};

}  // namespace shockfield::materials
