#pragma once
// Taylor homogenisation (Liu et al. 2025, eqs. 42-43): N_g grains at one material point share its
// deformation gradient, and the point's Cauchy stress is the volume average of the grains'
// stresses, ⟨σ⟩ = Σ v_g σ^g, with equal volumes v_g = 1/N_g (eq. 43). Stress equilibrium between
// the grains is not enforced (the Taylor assumption).
#include <vector>

#include "shockfield/materials/strength/crystal_viscoplasticity.hpp"

namespace shockfield::materials {

struct TaylorAggregate {
  CrystalViscoplasticity crystal;
  std::vector<Mat3> orientations;  ///< one g (crystal → sample) per grain

  using State = std::vector<CrystalViscoplasticity::State>;
  State initial_state() const;
  /// Advances every grain from F_old to F_new over dt; returns ⟨σ⟩ (eq. 43). A single grain's
  /// stress is returned as it is (bitwise the single-crystal law).
  Mat3 update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const;
  /// Mean accumulated slip γ_tot of the grains.
  static double accumulated_slip(const State& s);
};

}  // namespace shockfield::materials
