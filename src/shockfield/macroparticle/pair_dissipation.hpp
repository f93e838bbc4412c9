#pragma once
// The pairwise dissipation of Saitoh et al. eq 8, F_i,D = Σ_j μ (v_j − v_i) over the bonded
// neighbours (r < cutoff), with the pairwise random force that balances it at temperature T
// (fluctuation–dissipation, as in dissipative particle dynamics: Español and Warren 1995): each
// bond gets a Gaussian vector ξ_ij = −ξ_ji of variance 2μ k_B T/Δt per component, scaled by
// η_CG as eq 21 scales the random force. Action equals reaction, so momentum is conserved.
// Random numbers are keyed on (seed, step, bond ids): reproducible and thread independent; the
// loop is serial, so the sums are too.
#include <cstdint>

#include "shockfield/md/fix.hpp"

namespace shockfield::macroparticle {

class FixPairDissipation final : public md::Fix {
 public:
  /// Engine units: viscosity μ (mass/time), bath temperature (η_CG² T), bond cutoff.
  FixPairDissipation(double viscosity, double temperature, std::uint64_t seed, double cutoff)
      : viscosity_(viscosity), temperature_(temperature), seed_(seed), cutoff_(cutoff) {}
  std::string name() const override { return "pair_dissipation"; }
  void post_force(md::Simulation& sim) override;
  void end_of_step(md::Simulation& sim) override;
  double energy_added() const override { return energy_added_; }
  md::FixState state() const override { return {{"energy_added", "eV", {energy_added_}}}; }
  void restore(const md::FixState& s) override { energy_added_ = md::fix_state_value(s, name(), "energy_added"); }

 private:
  double viscosity_, temperature_;
  std::uint64_t seed_;
  double cutoff_;
  double energy_added_ = 0;
  std::vector<double> added_;  // per particle force (xyz) this fix added, for the energy account
};

}  // namespace shockfield::macroparticle
