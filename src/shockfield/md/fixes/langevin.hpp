#pragma once
// Langevin thermostat on a group (LAMMPS `fix langevin` + `fix nve`): in post_force each atom
// gets a friction −m v/τ and a random force of variance 2 m k_B T/(τ Δt) per component
// (fluctuation–dissipation), with Gaussian numbers from a counter-based generator keyed on
// (seed, step, atom id) so runs do not depend on threads or restarts. Tracks the energy it
// exchanges with the bath for the conserved-quantity column.
#include <cstdint>

#include "shockfield/core/types.hpp"
#include "shockfield/md/fixes/nve.hpp"

namespace shockfield::md {

class FixLangevin : public FixNve {
 public:
  FixLangevin(double temperature, double damping, std::uint64_t seed, std::uint32_t group_bit = 1u);
  std::string name() const override { return "langevin"; }
  void post_force(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;
  double energy_added() const override { return energy_added_; }
  FixState state() const override { return {{"energy_added", "eV", {energy_added_}}}; }
  void restore(const FixState& s) override { energy_added_ = fix_state_value(s, name(), "energy_added"); }

 private:
  double temperature_, damping_;
  std::uint64_t seed_;
  double energy_added_ = 0;
  std::vector<Vec3> bath_force_;
};

}  // namespace shockfield::md
