#pragma once
// The crystal viscoplastic law (materials/strength/crystal_viscoplasticity.hpp, seed 004 eqs.
// 18-41, Algorithm 1) as a correspondence material (constitutive.hpp): one grain of orientation
// g per point (a polycrystal gives each point its grain's g). Finite strain: the force uses
// P = det(F)·σ·F⁻ᵀ (eq. 10).
//
// The wave speed the Riemann impedance and the stable step need is the longitudinal modulus of
// the rotated cubic stiffness along the sample x axis (the impact direction),
//   M_x = c12 + 2c44 + (c11 − c12 − 2c44)·Σ_k a_k⁴,  a = gᵀ·e_x (direction cosines in the crystal),
// which is c11 along [100] and (c11 + 2c12 + 4c44)/3 along [111].
#include "shockfield/core/types.hpp"
#include "shockfield/materials/strength/crystal_viscoplasticity.hpp"

namespace shockfield::pd {

struct CrystalMaterial {
  double density = 0.0;                       ///< ρ0 [kg/m³]
  materials::CrystalViscoplasticity crystal;  ///< Table 1 parameters, slip systems
  Mat3 orientation = Mat3::Identity();        ///< g: crystal → sample
  double slope = 0.0;                         ///< s for the Riemann impedance (0: acoustic)

  using State = materials::CrystalViscoplasticity::State;
  State initial_state() const { return crystal.initial_state(orientation); }
  Mat3 update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const {
    return crystal.update(s, f_old, f_new, dt);
  }
  std::size_t state_size() const { return 29 + 2 * crystal.systems.size(); }
  void save(const State& s, double* out) const;
  void load(State& s, const double* in) const;
  bool finite_strain() const { return true; }
  double reference_density() const { return density; }
  double longitudinal_modulus() const;
  double hugoniot_slope() const { return slope; }
};

/// The plastic measure the run output reports: the grain's accumulated slip γ_tot (eq. 39).
inline double plastic_measure(const CrystalMaterial::State& s) { return s.accumulated_slip; }

}  // namespace shockfield::pd
