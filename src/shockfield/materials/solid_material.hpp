#pragma once
// A solid as the paper's MPM sees it (Xu et al. 2015, §2.2.1): Mie-Grüneisen pressure (eqs. 5-6), J2
// deviatoric strength (eqs. 1-4), temperature (eqs. 7-8), a bulk artificial viscosity and an
// optional tensile (spall) failure, plus
// the update of one material point over a step given its velocity gradient. The update is written
// once here so that every continuum method (mpm/, later pd/) shares it.
#include <string>

#include "shockfield/core/types.hpp"
#include "shockfield/materials/artificial_viscosity.hpp"
#include "shockfield/materials/eos/mie_gruneisen.hpp"
#include "shockfield/materials/spall.hpp"
#include "shockfield/materials/strength/j2_plasticity.hpp"
#include "shockfield/materials/thermal.hpp"

namespace shockfield::materials {

/// State of one material point (Cauchy stress σ = s − (P + q)I, eq. 1).
struct PointState {
  Mat3 deformation = Mat3::Identity();  ///< F
  J2Plasticity::State deviatoric;       ///< s, α, ε̄p
  double pressure = 0.0;                ///< P from the EOS [Pa]
  double viscous_pressure = 0.0;        ///< q [Pa]
  double energy = 0.0;                  ///< specific internal energy e [J/kg]
  double temperature = 0.0;             ///< T [K]
  double shock_volume = 0.0;            ///< smallest specific volume reached (eq. 7 bookkeeping) [m³/kg]
  double plastic_work = 0.0;            ///< accumulated specific plastic work W_p [J/kg]
  double sound_speed = 0.0;             ///< longitudinal speed √(c_b² + 4G/(3ρ)) [m/s]
  double damage = 0.0;                  ///< 0 intact, 1 failed in tension (spall.hpp)

  Mat3 stress() const { return deviatoric.s - (pressure + viscous_pressure) * Mat3::Identity(); }
};

struct SolidMaterial {
  std::string name;
  MieGruneisen eos;
  J2Plasticity strength;
  Thermal thermal;
  ArtificialViscosity viscosity;
  SpallFailure spall;  ///< off unless a spall strength is given

  /// InputError naming the material and the parameter when one is out of range.
  void validate() const;
  /// Longitudinal (elastic) wave speed √(c_b² + 4G/(3ρ)) at (ρ, e) [m/s].
  double longitudinal_speed(double rho, double e) const;
  /// The same at a Hugoniot point already evaluated.
  double longitudinal_speed(const MieGruneisen::HugoniotPoint& h, double e) const;
  /// Unstressed state at the reference density and the initial temperature.
  PointState initial_state() const;
  /// Advance a point with reference density rho_ref (= mass / initial volume) over dt with the
  /// velocity gradient L; `length` is the artificial-viscosity length (the cell size). With
  /// `plane_strain` (2D in x, y: L has no z row or column) the out-of-plane couplings are skipped.
  void update(PointState& p, double rho_ref, const Mat3& velocity_gradient, double dt, double length,
              bool plane_strain = false) const;

 private:
  /// The update with the coupled axes 0..N−1 (N = 2: plane strain, N = 3: 3D).
  template <int N>
  void update_coupled(PointState& p, double rho_ref, const Mat3& velocity_gradient, double dt, double length) const;
};

}  // namespace shockfield::materials
