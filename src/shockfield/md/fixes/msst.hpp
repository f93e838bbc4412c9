#pragma once
// The multi-scale shock technique (MSST; Reed, Fried & Joannopoulos, Phys. Rev. Lett. 90, 235503
// (2003)) with LAMMPS `fix msst` semantics: a periodic cell whose length along the shock axis is
// a dynamical variable, driven so that the cell follows a steady shock of speed U_s through the
// material. The volume V obeys (derivation in docs/theory/md-msst.md)
//   V̈ = (M/Q) [P_aa − p₀ − ρ₀U_s²(1 − V/V₀)] − (M μ/(Q V)) V̇                    (1)
// (M the total mass, Q the cell-mass-like parameter `q` in mass²/length⁴, μ the artificial
// viscosity, P_aa the pressure-tensor component along the axis a; the bracket is the distance
// from the Rayleigh line), and the atoms
//   v̇_i,k = f_i,k/m_i + D_i,k v_i,k,  D_i,k = μ V̇²/(m_i V Σ_j v_j²) − 2 δ_ka V̇/V       (2)
// with the affine rescaling of the cell along a (positions and v_a scaled by the volume ratio)
// done at each half volume step. The conserved quantity is
//   H = K + U + Q V̇²/(2M) − ½ M U_s² (1 − V/V₀)² − p₀ (V₀ − V)                     (3)
// (LAMMPS's econserve with the fix's scalar), from which energy_added() returns −(H − K − U).
// The integrator is LAMMPS's (half steps of (1) and (2) solved exactly for constant A, B, C, D,
// volume half steps around the drift), so the trajectory follows `fix msst` to round-off
// (tests/unit/md_msst). Reported (LAMMPS f_msst[1..4]): the Hugoniot deviation
//   dhugoniot = [½ (P_aa + p₀)(V₀ − V) + E₀ − E] / (N_f k_B)  (K)                    (4)
// the Rayleigh deviation drayleigh = P_aa − p₀ − ρ₀U_s²(1 − V/V₀) (bar), the Lagrangian (particle)
// speed U_p = U_s (1 − V/V₀) and the Lagrangian position x_L(t) = −∫ U_s V/V₀ dt.
#include <cstdint>
#include <optional>

#include "shockfield/md/fix.hpp"

namespace shockfield::md {

struct MsstSettings {
  int axis = 2;                    ///< shock direction
  double shock_speed = 0;          ///< U_s, Å/ps
  double q = 10;                   ///< cell mass-like parameter, amu²/Å⁴ (LAMMPS q)
  double mu = 0;                   ///< artificial viscosity, amu/(Å ps) (LAMMPS mu)
  std::optional<double> p0, v0, e0;  ///< reference state (bar, Å³, eV); default: at setup
  double tscale = 0.01;            ///< fraction of the kinetic energy moved into V̇ at setup
  std::int64_t stage_steps = 0;    ///< steps of the stage: its second half is averaged
};

/// The MSST quantities of the current state (LAMMPS f_msst and f_msst[1..4], and the state).
struct MsstQuantities {
  double energy = 0;               ///< eV, the fix's scalar: H − K − U of eq. (3)
  double dhugoniot = 0;            ///< K, eq. (4)
  double drayleigh = 0;            ///< bar
  double lagrangian_speed = 0;     ///< Å/ps, U_p = U_s (1 − V/V₀)
  double lagrangian_position = 0;  ///< Å
  double pressure_axis = 0;        ///< P_aa, bar
  double volume = 0;               ///< Å³
};

/// Means over the second half of the stage (the steady state), for the run summary.
struct MsstAverages {
  double samples = 0;
  double up = 0, pressure_axis = 0, volume = 0, temperature = 0;  ///< Å/ps, bar, Å³, K
};

class FixMsst : public Fix {
 public:
  explicit FixMsst(const MsstSettings& settings, std::uint32_t group_bit = 1u);
  std::string name() const override { return "msst"; }
  /// Total mass, the reference state (p₀ = P_aa, V₀, E₀ = K + U unless given) and the tscale
  /// transfer: V̇ = −√(tscale · M · 2K/Q), velocities scaled by √(1 − tscale).
  void setup(Simulation& sim) override;
  void initial_integrate(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  double energy_added() const override { return -scalar(); }
  FixState state() const override;
  void restore(const FixState& s) override;

  MsstQuantities quantities(const Simulation& sim) const;
  const MsstAverages& averages() const { return averages_; }
  const MsstSettings& settings() const { return settings_; }
  double v0() const { return v0_; }
  double p0() const { return p0_; }
  double e0() const { return e0_; }
  double total_mass() const { return total_mass_; }
  /// H of eq. (3) right after setup, eV (the reference of the conserved-quantity drift).
  double conserved_at_start() const { return h_start_; }

 private:
  double scalar() const;
  /// Half step of eq. (1) at the current pressure and volume.
  void cell_half_step(const Simulation& sim);
  /// Half step of eq. (2) for the group with Σv² = vsum.
  void velocity_half_step(Simulation& sim, double vsum) const;
  /// Cell and all atoms rescaled along the axis about the cell centre by `dilation`, v_a too.
  void remap(Simulation& sim, double dilation);

  MsstSettings settings_;
  std::uint32_t group_bit_;
  double total_mass_ = 0;  ///< amu
  double p0_ = 0, v0_ = 1, e0_ = 0;
  double omega_ = 0;       ///< V̇, Å³/ps
  double volume_ = 0;      ///< V after the last update, Å³
  double vsum_ = 0;        ///< Σ v² of the group, Å²/ps²
  double lagrangian_position_ = 0;
  double h_start_ = 0;
  std::int64_t steps_done_ = 0;
  MsstAverages averages_;
};

}  // namespace shockfield::md
