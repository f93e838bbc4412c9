#pragma once
// Contact laws of a granular chain: a small type with its parameters and force/energy/stiffness
// functions of one contact's overlap δ and overlap rate δ̇, evaluated by the generic loop of
// contact_loop.hpp (the shape of md/potentials/pair_loop.hpp's kernels). Per-contact stiffness
// coefficients κ come from the chain (Hertz formula, chain.hpp), so one law serves every contact.
#include <cmath>
#include <concepts>
#include <limits>

namespace shockfield::granular {

/// A normal contact law: force(κ, δ, δ̇) ≥ 0 (no tension), the elastic energy U(κ, δ) with
/// dU/dδ = the elastic part of the force, and the tangent stiffness dF/dδ.
template <class L>
concept ContactLaw = requires(const L& law, double kappa, double overlap, double rate) {
  { law.force(kappa, overlap, rate) } -> std::same_as<double>;
  { law.energy(kappa, overlap) } -> std::same_as<double>;
  { law.stiffness(kappa, overlap) } -> std::same_as<double>;
};

/// Hertz's law for two elastic spheres, F = κ δ^{3/2} for δ > 0 and 0 otherwise (no tension),
/// with an optional viscous dashpot γ δ̇ while in contact; the total is clipped at 0 so that a
/// separating damped contact never pulls (Hertz 1882; Johnson, Contact Mechanics, 1985, §4.2).
/// U = (2/5) κ δ^{5/2}, dF/dδ = (3/2) κ δ^{1/2}.
struct HertzContact {
  double damping = 0.0;  ///< γ [N·s/m]

  double force(double kappa, double overlap, double rate) const {
    const double d = overlap > 0.0 ? overlap : 0.0;
    const double elastic = kappa * d * std::sqrt(d);
    const double total = elastic + (overlap > 0.0 ? damping * rate : 0.0);
    return total > 0.0 ? total : 0.0;
  }
  double energy(double kappa, double overlap) const {
    const double d = overlap > 0.0 ? overlap : 0.0;
    return 0.4 * kappa * d * d * std::sqrt(d);
  }
  double stiffness(double kappa, double overlap) const {
    return overlap > 0.0 ? 1.5 * kappa * std::sqrt(overlap) : 0.0;
  }
};

/// Hertz's stiffness coefficient of two spheres (radius R2 = +inf for a flat wall):
/// κ = (4/3) E* √R*,  1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2,  1/R* = 1/R1 + 1/R2
/// (Johnson, Contact Mechanics, 1985, eqs. 4.22–4.23). E2 = +inf is a rigid body.
inline double hertz_kappa(double E1, double nu1, double R1, double E2, double nu2, double R2) {
  const double inv_E = (1.0 - nu1 * nu1) / E1 + (std::isinf(E2) ? 0.0 : (1.0 - nu2 * nu2) / E2);
  const double inv_R = 1.0 / R1 + (std::isinf(R2) ? 0.0 : 1.0 / R2);
  return (4.0 / 3.0) * (1.0 / inv_E) * std::sqrt(1.0 / inv_R);
}

}  // namespace shockfield::granular
