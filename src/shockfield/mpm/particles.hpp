#pragma once
// Material points (Xu et al. 2015, §2.2.2): each carries mass m_p, position x_p, velocity v_p and the
// constitutive state. Kinematic fields are structure-of-arrays; the constitutive state is one
// materials::PointState per point because the material update reads and writes all of it at
// once. In 2D (plane strain) z components are zero and the volume is per metre of thickness.
#include <Eigen/LU>
#include <cstddef>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/materials/solid_material.hpp"

namespace shockfield::mpm {

struct Particles {
  std::vector<Vec3> x;                   ///< position [m]
  std::vector<Vec3> v;                   ///< velocity [m/s]
  std::vector<double> mass;              ///< m_p [kg] (per metre in 2D), fixed
  std::vector<double> volume0;           ///< initial volume [m³] (m² in 2D)
  std::vector<Vec3> half_size;           ///< GIMP half-width of the particle box per axis [m]
  std::vector<int> material;             ///< index into the simulation's material list
  std::vector<int> body;                 ///< contact body (contact.hpp): one grid field per body with contact on
  std::vector<Mat3> velocity_gradient;   ///< L_p of the last step [1/s]
  std::vector<materials::PointState> state;

  std::size_t size() const { return x.size(); }
  /// Append one point of `mat` (index `material_id`) at rest state, at its reference density.
  void add(const Vec3& position, const Vec3& velocity, double volume, const Vec3& half,
           const materials::SolidMaterial& mat, int material_id, int body_id = 0);
  /// Current density m_p / (V0 det F) [kg/m³].
  double density(std::size_t p) const { return mass[p] / (volume0[p] * state[p].deformation.determinant()); }
  /// Current volume V0 det F.
  double volume(std::size_t p) const { return volume0[p] * state[p].deformation.determinant(); }
};

/// Conserved totals, summed in particle order (so independent of the thread count).
struct Totals {
  double mass = 0.0;
  Vec3 momentum = Vec3::Zero();
  double kinetic = 0.0;   ///< Σ ½ m v²
  double internal = 0.0;  ///< Σ m e (EOS, elastic and dissipated energy)
  double total() const { return kinetic + internal; }
};
Totals totals(const Particles& p);

}  // namespace shockfield::mpm
