#pragma once
// The interface between the time integrator (simulation.hpp) and a peridynamic force law: the
// force density L of Liu et al. (2025) eq. 1 at every point from the current positions y and velocities v.
// Implementations (bond_force.hpp: PMB, LPS; correspondence.hpp) are templates over small model
// types; this virtual call happens once per step, never per bond.
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield::pd {

struct Kinematics {
  const std::vector<Vec3>& y;  ///< current positions x + u [m]
  const std::vector<Vec3>& v;  ///< velocities at the force evaluation (v_{n+1/2} in velocity-Verlet) [m/s]
  double dt;                   ///< step the state is advanced over (0 at setup) [s]
};

class ForceModel {
 public:
  virtual ~ForceModel() = default;
  /// Fills force_density[i] = L(x_i) (force per volume); advances any internal
  /// state (damage, plastic variables) by k.dt.
  virtual void compute(const Kinematics& k, std::vector<Vec3>& force_density) = 0;
  /// Stable velocity-Verlet step at the reference state for the densities ρ_i [s].
  virtual double stable_step(const std::vector<double>& density) const = 0;
  /// Damage φ_i ∈ [0, 1]: the fraction of the family's volume Σ V_j (without the partial-volume
  /// factor, as LAMMPS compute damage/atom) whose bonds are broken.
  virtual std::vector<double> damage() const = 0;
  virtual std::string name() const = 0;
};

}  // namespace shockfield::pd
