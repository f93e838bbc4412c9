#pragma once
// The Hugoniostat (Ravelo, Holian, Germann & Lomdahl, Phys. Rev. B 70, 014103 (2004)) with LAMMPS
// `fix nphug` semantics: the Nosé–Hoover barostat of `fix npt` (fixes/nose_hoover_npt.hpp,
// which this fix extends) drives the pressure (the component P_aa along a for a uniaxial style x,
// y or z; the scalar pressure for iso and aniso) to the target P, while the thermostat's target
// temperature is replaced every step by the temperature that would put the current state on the
// Hugoniot of the reference state (p₀, V₀, E₀):
//   T_target = T + Δ_H,   Δ_H = [½ (p + p₀)(V₀ − V) + E₀ − E] / (N_f k_B)                  (1)
// (E = K + U, N_f = 3N − 3; Δ_H is the energy missing to the Rankine–Hugoniot energy condition
//   E − E₀ = ½ (p + p₀)(V₀ − V)                                                          (2)
// as a temperature). At equilibrium ⟨Δ_H⟩ = 0: the state is the Hugoniot point of pressure P.
// Reported (LAMMPS f_ID[1..3]): Δ_H, the shock and particle speeds of that point from the
// Rayleigh line and the strain ε = 1 − V/V₀,
//   U_s = √((p − p₀)/(ρ₀ ε)),   U_p = ε U_s                                               (3)
// (U_s = 0 when ε < 1e-10 or p < p₀; ρ₀ = M/V₀). As LAMMPS: p₀, V₀, E₀ are the state at the
// start of the stage unless given; the thermostat and barostat masses are set from the
// temperature at the start and kept (eta_mass_flag = omega_mass_flag = etap_mass_flag = 0); the
// MTK terms of a uniaxial barostat are LAMMPS's (NptSettings::lammps_mtk); the target is 0.01 K
// until the first Hugoniot target (LAMMPS FixNPHug::setup), which the barostat chain's first half
// step uses. The trajectories agree with LAMMPS's to round-off (tests/unit/md_nphug).
#include <cstdint>
#include <optional>

#include "shockfield/md/fixes/nose_hoover_npt.hpp"

namespace shockfield::md {

struct NphugSettings {
  NptSettings npt;                 ///< pressure, damping (τ_T), pressure_damping, dims, iso, chains
  int axis = -1;                   ///< uniaxial direction (x, y, z: 0, 1, 2) or −1 (iso, aniso)
  std::optional<double> p0, v0, e0;  ///< reference state (bar, Å³, eV); default: at setup
  std::int64_t stage_steps = 0;    ///< steps of the stage: its second half is averaged
};

/// The Hugoniostat quantities of the current state.
struct NphugQuantities {
  double dhugoniot = 0;    ///< K, Δ_H of eq. (1)
  double us = 0, up = 0;   ///< Å/ps, eq. (3)
  double pressure = 0;     ///< bar, P_aa (uniaxial) or the scalar pressure
  double volume = 0;       ///< Å³
};

/// Sums over the second half of the stage (divided in the report).
struct NphugAverages {
  double samples = 0;
  double pressure = 0, volume = 0, temperature = 0, energy = 0, dhugoniot = 0;  ///< bar, Å³, K, eV, K
};

class FixNphug : public FixNoseHooverNpt {
 public:
  explicit FixNphug(const NphugSettings& settings, std::uint32_t group_bit = 1u);
  std::string name() const override { return "nphug"; }
  /// The reference state and the masses' temperature (the current one; RunError if it is 0).
  void setup(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  FixState state() const override;
  void restore(const FixState& s) override;

  NphugQuantities quantities(const Simulation& sim) const;
  const NphugAverages& averages() const { return averages_; }
  const NphugSettings& settings() const { return settings_; }
  double v0() const { return v0_; }
  double p0() const { return p0_; }
  double e0() const { return e0_; }
  double total_mass() const { return total_mass_; }
  /// The thermostat's target of the last step, K.
  double last_target() const { return target_; }

 protected:
  /// T + Δ_H, eq. (1).
  double target_temperature(const Simulation& sim) override;

 private:
  NphugSettings settings_;
  std::uint32_t group_bit_;
  double total_mass_ = 0;  ///< amu
  double p0_ = 0, v0_ = 1, e0_ = 0;
  double target_ = 0;      ///< K
  std::int64_t steps_done_ = 0;
  NphugAverages averages_;
};

}  // namespace shockfield::md
