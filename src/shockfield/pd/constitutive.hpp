#pragma once
// Constitutive models the correspondence force (correspondence.hpp) evaluates at every point:
// each is a small type with its State and one update from the old and new non-local deformation
// gradient F (Liu et al. 2025, eq. 8) to the Cauchy stress σ. A model also tells the force how to turn σ
// into the first Piola-Kirchhoff stress (eq. 10, P = det(F)·σ·F⁻ᵀ, or P = σ for small strain)
// and its wave speeds for the Riemann correction and the stable step.
#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/materials/strength/j2_plasticity.hpp"

namespace shockfield::pd {

/// One named part of a material's saved point state, `count` values per point (and grain).
struct StateField {
  std::string name;
  std::string units;  ///< "1" for a pure number
  std::size_t count = 1;
  bool integer = false;  ///< a counter, stored as an integer
};

/// What a material's save()/load() write per point: the fields in order, the whole list repeated
/// for each of `grains` grains when `per_grain` (a Taylor aggregate), else once.
struct StateLayout {
  std::vector<StateField> fields;
  bool per_grain = false;
  std::size_t grains = 1;
  std::size_t grain_size() const;  ///< Σ count
  std::size_t size() const { return grains * grain_size(); }  ///< doubles per point
};

template <class M>
concept CorrespondenceMaterial = requires(const M& m, typename M::State& s, const Mat3& f, double* out) {
  { m.initial_state() } -> std::same_as<typename M::State>;  // the unloaded state of a point
  { m.update(s, f, f, 0.0) } -> std::same_as<Mat3>;  // σ at the new F, advancing s over dt
  { m.state_layout() } -> std::same_as<StateLayout>;  // what save()/load() write (checkpoints)
  m.save(std::as_const(s), out);
  m.load(s, std::as_const(out));
  { m.finite_strain() } -> std::convertible_to<bool>;
  { m.reference_density() } -> std::convertible_to<double>;
  { m.longitudinal_modulus() } -> std::convertible_to<double>;  // M = ρ0·c_L² [Pa]
  { m.hugoniot_slope() } -> std::convertible_to<double>;        // s of Us = a + s·Up [-]
};

/// Small-strain isotropic elasticity with J2 plasticity (the paper's validation material, §3.1):
/// ε = sym(F) − I, pressure from the bulk modulus (σ_m = K·tr ε), deviator by the radial return
/// of materials::J2Plasticity on the increment of dev ε. P = σ (linear kinematics), so a 1D bar
/// has exactly the elastic speed √((K + 4G/3)/ρ) and the plastic speed √(K/ρ).
struct SmallStrainJ2 {
  double density = 0.0;                 ///< ρ0 [kg/m³]
  double bulk = 0.0;                    ///< K [Pa]
  materials::J2Plasticity deviatoric;   ///< G, Y, hardening
  double slope = 0.0;                   ///< s for the Riemann impedance (0: acoustic)

  struct State {
    Mat3 strain = Mat3::Zero();
    materials::J2Plasticity::State dev;
  };
  /// From E, ν, Y and a linear hardening modulus (InputError on bad values).
  static SmallStrainJ2 from_young(double density, double young, double poisson, double yield, double hardening,
                                  double slope);
  State initial_state() const { return {}; }
  Mat3 update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const;
  /// strain, deviatoric_stress, back_stress (9 each, row-major), plastic_strain.
  StateLayout state_layout() const;
  void save(const State& s, double* out) const;
  void load(State& s, const double* in) const;
  bool finite_strain() const { return false; }
  double reference_density() const { return density; }
  double longitudinal_modulus() const { return bulk + 4.0 / 3.0 * deviatoric.shear_modulus; }
  double hugoniot_slope() const { return slope; }
};

/// The plastic measure the run output reports: the equivalent plastic strain ε̄p.
inline double plastic_measure(const SmallStrainJ2::State& s) { return s.dev.plastic_strain; }

}  // namespace shockfield::pd
