#pragma once
// Nosé–Hoover chain thermostat with velocity-Verlet (LAMMPS `fix nvt`, Martyna, Tuckerman &
// Klein, Mol. Phys. 87, 1117 (1996)): a chain of M thermostat variables (default 3) is advanced
// by a quarter/eighth-step Trotter split before the first and after the second velocity half
// kick; the atoms' velocities are scaled by exp(−½Δt η̇₁). Thermostat masses
// Q₁ = N_f k_B T / ω², Q_k = k_B T / ω² with ω = 1/τ. The chain energy
// N_f k_B T η₁ + Σ_{k>1} k_B T η_k + Σ ½ Q_k η̇_k² enters the conserved quantity. A chain starts
// at rest with the outer members' forces −ω² (LAMMPS FixNH::setup).
#include "shockfield/core/units.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/fixes/nve.hpp"

namespace shockfield::md {

/// One Nosé–Hoover chain (MTK 1996 eq. 2; LAMMPS fix_nh.cpp nhc_temp_integrate and, for the
/// barostat, nhc_press_integrate) coupled to degrees of freedom of kinetic energy K: the first
/// member drives 2K towards L k_B T, member k > 1 drives Q_{k−1} η̇²_{k−1} towards k_B T.
class NoseHooverChain {
 public:
  NoseHooverChain(int length, double temperature, double period);
  /// A chain of length 0 is no chain: half_step() returns 1 and energy() 0 (LAMMPS pchain 0).
  /// Advances the chain by half a step Δt/2 given 2K of the coupled degrees of freedom, their
  /// number L (the target 2K is L k_B T) and the first mass Q₁ = first_mass_dof · k_B T / ω².
  /// Returns exp(−½Δt η̇₁), the factor by which the coupled velocities must be scaled.
  double half_step(double twice_ke, double dof, double first_mass_dof, double dt);
  /// L k_B T η₁ + Σ_{k>1} k_B T η_k + Σ ½ Q_k η̇_k² (eV).
  double energy() const;
  /// Appends the chain variables to `s` as <prefix>eta, _eta_dot, _eta_dotdot, _mass (one value
  /// per member) and _dof; restore() reads them back (InputError naming `fix` when absent).
  void save(FixState& s, const std::string& prefix) const;
  void restore(const FixState& s, const std::string& fix, const std::string& prefix);
  double degrees_of_freedom() const { return dof_; }
  double temperature() const { return kt_ / units::metal::boltz; }
  /// A new target temperature with the masses kept at the temperature they were built with
  /// (LAMMPS fix nphug: eta_mass_flag = etap_mass_flag = 0, the target moves every step).
  void retarget(double temperature) { kt_ = units::metal::boltz * temperature; }
  int length() const { return static_cast<int>(eta_.size()); }

 private:
  double kt_, mass_kt_, period_;  ///< k_B T of the target and of the masses
  double dof_ = 0;
  std::vector<double> eta_, eta_dot_, eta_dotdot_, mass_;
};

class FixNoseHoover : public FixNve {
 public:
  FixNoseHoover(double temperature, double damping, int chain = 3, std::uint32_t group_bit = 1u);
  std::string name() const override { return "nvt"; }
  void initial_integrate(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;
  double energy_added() const override { return -chain_.energy(); }
  FixState state() const override;
  void restore(const FixState& s) override { chain_.restore(s, name(), "thermostat"); }

 private:
  /// Advances the chain by half a step and scales the group's velocities.
  void integrate_chain(Simulation& sim);
  NoseHooverChain chain_;
};

/// The run-time diagnosis of a thermostat or barostat that ran away: RunError when the energy
/// its extended variables hold (`energy`, eV) is not finite or exceeds runaway_factor · N_f k_B T
/// of the atoms it couples to. A time step too large for the chain blows the system up while
/// the velocity scaling keeps every atom finite and slow, so the atoms' checks never fire; only
/// the conserved quantity shows it (3e22 eV for 256 atoms at dt = 0.1 ps).
void check_extended_energy(const Simulation& sim, const char* fix, double energy, double dof, double temperature);
/// A legitimate run's thermostat holds a few N_f k_B T; a million is a runaway.
inline constexpr double runaway_factor = 1e6;

/// Scales the velocities of a group's atoms by `factor`.
void scale_group_velocities(Atoms& atoms, std::uint32_t group_bit, double factor);

}  // namespace shockfield::md
