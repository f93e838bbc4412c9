#pragma once
// The crystal viscoplastic law (materials/strength/crystal_viscoplasticity.hpp, Liu et al. (2025) eqs.
// 18-41, Algorithm 1) as a correspondence material (constitutive.hpp): each point holds N_g grains
// of orientations g (crystal → sample) that share its deformation gradient, and its stress is
// their Taylor average (eqs. 42-43; N_g = 1 is a single crystal, or one grain of a polycrystal).
// Finite strain: the force uses P = det(F)·σ·F⁻ᵀ (eq. 10).
//
// The wave speed the Riemann impedance and the stable step need is the longitudinal modulus of
// the rotated cubic stiffness along the sample x axis (the impact direction),
//   M_x = c12 + 2c44 + (c11 − c12 − 2c44)·Σ_k a_k⁴,  a = gᵀ·e_x (direction cosines in the crystal),
// which is c11 along [100] and (c11 + 2c12 + 4c44)/3 along [111]. For N_g grains it is the mean of
// the grains' M_x: under the Taylor assumption the stiffness is the Voigt average.
#include "shockfield/core/types.hpp"
#include "shockfield/materials/strength/crystal_taylor.hpp"
#include "shockfield/pd/constitutive.hpp"

namespace shockfield::pd {

struct CrystalMaterial {
  double density = 0.0;                        ///< ρ0 [kg/m³]
  materials::TaylorAggregate aggregate{materials::CrystalViscoplasticity::ofhc_copper(),
                                       {Mat3::Identity()}};  ///< Table 1 law and the grains' g
  double slope = 0.0;                          ///< s for the Riemann impedance (0: acoustic)

  using State = materials::TaylorAggregate::State;
  State initial_state() const { return aggregate.initial_state(); }
  Mat3 update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const {
    return aggregate.update(s, f_old, f_new, dt);
  }
  /// Per grain: orientation g, lattice (g·Re), plastic_deformation_gradient Fp (9 each),
  /// slip_resistance g^α [Pa] and slip γ^α (one per slip system), accumulated_slip, substeps.
  StateLayout state_layout() const;
  void save(const State& s, double* out) const;
  void load(State& s, const double* in) const;
  bool finite_strain() const { return true; }
  double reference_density() const { return density; }
  double longitudinal_modulus() const;
  double hugoniot_slope() const { return slope; }
};

/// The plastic measure the run output reports: the accumulated slip γ_tot (eq. 39), mean over
/// the point's grains.
inline double plastic_measure(const CrystalMaterial::State& s) {
  return materials::TaylorAggregate::accumulated_slip(s);
}

}  // namespace shockfield::pd
