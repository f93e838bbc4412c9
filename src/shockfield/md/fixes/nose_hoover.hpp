#pragma once
// Nosé–Hoover chain thermostat with velocity-Verlet (LAMMPS `fix nvt`, Martyna, Tuckerman &
// Klein, Mol. Phys. 87, 1117 (1996)): a chain of M thermostat variables (default 3) is advanced
// by a quarter/eighth-step Trotter split before the first and after the second velocity half
// kick; the atoms' velocities are scaled by exp(−½Δt η̇₁). Thermostat masses
// Q₁ = N_f k_B T / ω², Q_k = k_B T / ω² with ω = 1/τ. The chain energy
// N_f k_B T η₁ + Σ_{k>1} k_B T η_k + Σ ½ Q_k η̇_k² enters the conserved quantity.
#include "shockfield/md/fixes/nve.hpp"

namespace shockfield::md {

class FixNoseHoover : public FixNve {
 public:
  FixNoseHoover(double temperature, double damping, int chain = 3, std::uint32_t group_bit = 1u);
  std::string name() const override { return "nvt"; }
  void initial_integrate(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;
  double energy_added() const override;
  std::vector<double> state() const override;
  void restore(const std::vector<double>& s) override;

 private:
  /// Advances the chain by half a step and scales the group's velocities.
  void integrate_chain(Simulation& sim);
  double target_, period_;
  double dof_ = 0;
  std::vector<double> eta_, eta_dot_, eta_dotdot_, mass_;
};

}  // namespace shockfield::md
