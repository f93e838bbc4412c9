#pragma once
// Energy minimisation by FIRE (Bitzek et al., PRL 97, 170201 (2006)) with optional relaxation of
// the box lengths towards a target pressure. The box lengths are extra degrees of freedom with
// generalised force ∂(−H)/∂L_d = (P_dd − P_target)·V/L_d (enthalpy H = E + P_target V) and a
// fictitious mass; atoms follow a length change affinely. Stops when the largest atomic force is
// below `force_tolerance`, every relaxed P_dd is within `pressure_tolerance` of the target, or
// after `max_iterations`. Atoms outside `group` are held where they are (their forces are set to
// zero, as LAMMPS `fix setforce 0.0 0.0 0.0` on them during `minimize`): a frozen shell keeps a
// defect's far field in place.
#include <array>
#include <cstdint>
#include <string>

#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

struct MinimizeSettings {
  double force_tolerance = 1e-6;       ///< eV/Å
  double pressure_tolerance = 1.0;     ///< bar
  long long max_iterations = 100000;
  std::array<bool, 3> relax_box{false, false, false};
  double target_pressure = 0.0;        ///< bar
  double max_timestep_factor = 10.0;   ///< FIRE Δt_max = factor · Δt
  std::uint32_t group = 1;             ///< mask bit(s) of the atoms that move; bit 0 = all
};

struct MinimizeResult {
  long long iterations = 0;
  double energy = 0;          ///< eV
  double max_force = 0;       ///< eV/Å
  Vec3 pressure = Vec3::Zero();  ///< bar, diagonal
  bool converged = false;
  std::string reason;
};

MinimizeResult minimize_fire(Simulation& sim, const MinimizeSettings& settings);

}  // namespace shockfield::md
