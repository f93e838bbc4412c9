#pragma once
// J2 (von Mises) plasticity for the deviatoric stress (Xu et al. 2015, §2.2.1, eqs. 1-4): isotropic
// linear elasticity s = 2G·e^e with G = E/(2(1+ν)) (the paper's s = [E/(1+ν)]e^e), the yield
// criterion √(3/2)‖ξ‖ = σ_Y (eq. 3) on the shifted stress ξ = s − α, and linear hardening
// σ_Y = σ_Y0 + E_tan·ε̄p (eq. 4), where ε̄p = Σ√(2/3)‖Δe^p‖ is the accumulated equivalent
// plastic strain (equal to the plastic strain of a uniaxial tension test).
//
// Mixed hardening (Hughes 1984; Simo & Hughes, Computational Inelasticity, 1998, §3.3): a
// fraction β of E_tan hardens isotropically and 1 − β kinematically through the back stress α,
// dα = (2/3)(1 − β)E_tan·Δe^p. β = 1 (default) is eq. 4 exactly.
//
// The update is the radial return (Wilkins 1964; Simo & Hughes Box 3.2):
//   ξ* = s + 2GΔe − α,  f = √(3/2)‖ξ*‖ − σ_Y(ε̄p),  Δε̄p = f / (3G + E_tan)  if f > 0,
//   n = ξ*/‖ξ*‖,  Δe^p = √(3/2)Δε̄p·n,  s = s + 2G(Δe − Δe^p),  α += (2/3)(1−β)E_tan·Δe^p.
#include <cmath>
#include <string>

#include "shockfield/core/types.hpp"

namespace shockfield::materials {

struct J2Plasticity {
  double shear_modulus = 0.0;        ///< G [Pa]
  double yield_stress0 = 0.0;        ///< σ_Y0 [Pa]
  double tangent_modulus = 0.0;      ///< E_tan of eq. 4 [Pa]
  double isotropic_fraction = 1.0;   ///< β: 1 isotropic, 0 kinematic [-]

  /// From Young's modulus E and Poisson's ratio ν (G = E/(2(1+ν))).
  static J2Plasticity from_young(double young, double poisson, double yield0, double tangent,
                                 double isotropic_fraction = 1.0);

  /// Deviatoric state of one material point.
  struct State {
    Mat3 s = Mat3::Zero();            ///< deviatoric Cauchy stress [Pa]
    Mat3 back_stress = Mat3::Zero();  ///< α [Pa]
    double plastic_strain = 0.0;      ///< ε̄p [-]
  };
  /// What one update did: the plastic strain increment (traceless) and its equivalent measure.
  struct Increment {
    Mat3 plastic = Mat3::Zero();   ///< Δe^p
    double equivalent = 0.0;       ///< Δε̄p = √(2/3)‖Δe^p‖
  };

  void validate(const std::string& where) const;
  /// Current yield stress σ_Y(ε̄p) (eq. 4) [Pa].
  double yield_stress(double plastic_strain) const {
    return yield_stress0 + isotropic_fraction * tangent_modulus * plastic_strain;  // eq. 4
  }
  /// The evaluation function: advance `state` by the traceless strain increment `de`. (Inline:
  /// it runs once per material-point update.) N = 2 for plane strain (x, y): only the
  /// coefficients a plane-strain deviator can have (xx, yx, xy, yy, zz) are formed, the others
  /// being zero. Coefficient by coefficient, so that a caller's local state stays in registers.
  template <int N = 3>
  Increment update(State& state, const Mat3& de) const {
    const double g = shear_modulus;
    double* s = state.s.data();
    const bool kinematic = isotropic_fraction < 1.0;  // α ≡ 0 otherwise: ξ = s, α unchanged
    const double* alpha = state.back_stress.data();
    Mat3 xi;
    for (int k = 0; k < 9; ++k) {
      if (!plane_coefficient<N>(k)) continue;
      s[k] += 2.0 * g * de.data()[k];  // elastic trial, s = 2G·e^e
      xi.data()[k] = kinematic ? s[k] - alpha[k] : s[k];
    }
    const double xi_norm = std::sqrt(contract<N>(xi, xi));
    const double f = std::sqrt(1.5) * xi_norm - yield_stress(state.plastic_strain);  // eq. 3
    Increment inc;
    if (f <= 0.0) return inc;
    inc.equivalent = f / (3.0 * g + tangent_modulus);
    const double scale = std::sqrt(1.5) * inc.equivalent / xi_norm;
    const double hardening = (2.0 / 3.0) * (1.0 - isotropic_fraction) * tangent_modulus;
    for (int k = 0; k < 9; ++k) {
      if (!plane_coefficient<N>(k)) continue;
      const double dep = scale * xi.data()[k];
      inc.plastic.data()[k] = dep;
      s[k] -= 2.0 * g * dep;
      if (kinematic) state.back_stress.data()[k] += hardening * dep;
    }
    state.plastic_strain += inc.equivalent;
    return inc;
  }

  /// Whether coefficient k (column-major) of a deviator is formed: all for N = 3, and xx, yx,
  /// xy, yy, zz in plane strain (N = 2).
  template <int N>
  static constexpr bool plane_coefficient(int k) {
    return N == 3 || k == 0 || k == 1 || k == 3 || k == 4 || k == 8;
  }
  /// a:b = Σ a_ij b_ij over those coefficients, summed in the order of Eigen's vectorised
  /// a.cwiseProduct(b).sum() (pairs of consecutive coefficients, then the two lanes, then the
  /// ninth; the zero terms of plane strain dropped), on scalars.
  template <int N = 3>
  static double contract(const Mat3& a, const Mat3& b) {
    auto t = [&](int k) { return a.data()[k] * b.data()[k]; };
    if constexpr (N == 2) return ((t(0) + t(4)) + (t(1) + t(3))) + t(8);
    else return (((t(0) + t(2)) + (t(4) + t(6))) + ((t(1) + t(3)) + (t(5) + t(7)))) + t(8);
  }
};

/// Equivalent (von Mises) stress √(3/2)‖s‖ of eq. 3 [Pa].
double von_mises(const Mat3& s);
/// Traceless part of a tensor.
inline Mat3 deviator(const Mat3& a) { return a - (a.trace() / 3.0) * Mat3::Identity(); }

}  // namespace shockfield::materials
