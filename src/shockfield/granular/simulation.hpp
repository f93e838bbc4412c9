#pragma once
// A granular chain run: the chain (chain.hpp), the impulse on its top grain, Hertz contacts
// (contact_law.hpp) and the velocity-Verlet loop (LAMMPS fix nve):
//   v ← v + ½Δt f/m;  w ← w + Δt v;  f ← f(w, v);  v ← v + ½Δt f/m
// (the damping sees the half-step velocity). Displacements w are from the initial static
// equilibrium, so energies are reported relative to it: kinetic Σ ½mv², potential
// Σ_k [U(δ_k) − U(δ⁰_k)] − Σ_i m_i g w_i (contacts and wall), total = their sum.
//
// Stable step (docs/theory/granular.md): Verlet is stable for Δt < 2/ω_max, and by Gershgorin's
// theorem ω_max² ≤ max_i 2(k_{i−1} + k_i)/m_i with k = dF/dδ = (3/2)κ δ^{1/2} the tangent
// stiffness of the contacts on either side of grain i. The overlap bound is δ⁰_k plus the overlap
// that takes up all of the impulse's energy E: (2/5)κ x^{5/2} = E (a strict bound without a force
// history; with one, E is taken from the push's peak force and total impulse, an estimate).
#include <optional>
#include <vector>

#include "shockfield/granular/chain.hpp"
#include "shockfield/granular/contact_law.hpp"

namespace shockfield::granular {

/// The load on the top of the chain: a velocity v0 (+ down) given at t = 0 to grains
/// [0, grains), or a force history on grain 0, piecewise linear through (times, forces) and zero
/// outside them.
struct Impulse {
  enum class Kind { velocity, force };
  Kind kind = Kind::velocity;
  double velocity = 0.0;  ///< [m/s]
  long long grains = 1;
  std::vector<double> times;   ///< [s], increasing
  std::vector<double> forces;  ///< [N]
  double force_at(double t) const;
  /// The energy scale of the stable-step bound [J] (see the header comment).
  double energy_bound(const Chain& chain) const;
};

struct Thermo {
  long long step = 0;
  double time = 0.0;
  double kinetic = 0.0;
  double potential = 0.0;
  double total = 0.0;
  double external_work = 0.0;  ///< work of the force history so far (trapezoid rule) [J]
  double signal_depth = 0.0;   ///< depth of the fastest grain [m]
};

class Simulation {
 public:
  /// Without `time_step` the step is `safety` × the stable step. InputError when the given step
  /// is above the stable one or the impulse does not fit the chain.
  Simulation(Chain chain, Impulse impulse, std::optional<double> time_step = std::nullopt,
             double safety = 0.05);

  /// The stable-step estimate of this chain under this impulse [s].
  static double stable_step(const Chain& chain, const Impulse& impulse);

  void step();
  /// RunError when a value is no longer finite or the stiffest contact now needs a smaller step.
  void health_check() const;
  Thermo thermo() const;

  /// Puts back a checkpointed state; the next step continues bitwise as if never stopped.
  /// `force` and `contact_force` are those of the last evaluation (a damped law saw the half-step
  /// velocity, which a recomputation from the saved state would not reproduce).
  void restore(std::vector<double> w, std::vector<double> v, std::vector<double> force,
               std::vector<double> contact_force, long long steps, double time, double external_work);

  const Chain& chain() const { return chain_; }
  const Impulse& impulse() const { return impulse_; }
  const HertzContact& law() const { return law_; }
  double time_step() const { return dt_; }
  long long step_count() const { return steps_; }
  double time() const { return time_; }
  std::size_t size() const { return chain_.size(); }
  const std::vector<double>& displacement() const { return w_; }
  const std::vector<double>& velocity() const { return v_; }
  /// F_k of contact (k, k+1) at the last force evaluation [N].
  const std::vector<double>& contact_force() const { return contact_force_; }
  /// f_i on each grain at the last force evaluation [N].
  const std::vector<double>& force() const { return f_; }
  /// w, v and f for edits between steps (Method::state_arrays): the next step starts from them.
  std::vector<double>& displacement() { return w_; }
  std::vector<double>& velocity() { return v_; }
  std::vector<double>& force() { return f_; }
  double overlap(std::size_t k) const { return chain_.rest_overlap[k] + w_[k] - w_[k + 1]; }
  double wall_overlap() const { return chain_.wall_rest_overlap + w_.back(); }
  double wall_force() const { return wall_force_; }
  /// The force of contact k (k = N − 1: the wall) in the initial configuration [N].
  double rest_force(std::size_t k) const {
    return k + 1 < size() ? law_.force(chain_.kappa[k], chain_.rest_overlap[k], 0.0)
                          : law_.force(chain_.wall_kappa, chain_.wall_rest_overlap, 0.0);
  }
  /// Depth of grain i's centre now [m].
  double position(std::size_t i) const { return chain_.depth[i] + w_[i]; }
  /// Energy above the equilibrium held by grains [first, last) and the contacts between them.
  double excess_energy(std::size_t first, std::size_t last) const;

 private:
  void compute_forces();

  Chain chain_;
  Impulse impulse_;
  HertzContact law_;
  double dt_ = 0.0;
  std::vector<double> w_, v_, f_, contact_force_;
  double wall_force_ = 0.0;
  double top_force_ = 0.0;
  double external_work_ = 0.0;
  long long steps_ = 0;
  double time_ = 0.0;
};

}  // namespace shockfield::granular
