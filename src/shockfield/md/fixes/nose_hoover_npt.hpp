#pragma once
// Isothermal–isobaric integration (LAMMPS `fix npt temp T T τ_T iso|aniso|x|y|z P P τ_P`):
// the Martyna–Tobias–Klein equations (MTK, J. Chem. Phys. 101, 4177 (1994)) integrated with
// the Trotter split of Tuckerman et al., J. Phys. A 39, 5629 (2006) as LAMMPS fix_nh.cpp does
// (Shinoda, Shiga & Mikami, Phys. Rev. B 69, 134103 (2004)). Variables: a Nosé–Hoover chain on
// the atoms, a log-strain rate ω̇_d per barostatted dimension d with mass
// W = (N+1) k_B T / ω_P² (ω_P = 1/τ_P; LAMMPS's choice), and a chain on the barostat. Per step:
//   initial_integrate: barostat chain ½Δt; atom chain ½Δt; ω̇ kick ½Δt; v ← v e^{−½Δt(ω̇_d+μ)};
//                      v ← v + ½Δt f/m; box dilation e^{½Δt ω̇_d}; x ← x + Δt v; dilation again
//   final_integrate:   v ← v + ½Δt f/m; v ← v e^{−½Δt(ω̇_d+μ)}; ω̇ kick ½Δt; atom chain ½Δt;
//                      barostat chain ½Δt
// with the ω̇ kick (MTK 1994 eq. 2.9, per dimension)
//   W dω̇_d/dt = V (P_d − P_target) + 2K/(3N)                           (1)
// and the MTK velocity coupling μ = Σ_d ω̇_d / (3N)                     (2)
// (P_d: the scalar pressure for iso, the diagonal tensor component for aniso; K: the group's
// kinetic energy; N: atoms). With all three dimensions barostatted (1–2) are LAMMPS's
// mtk_term1/mtk_term2; for a subset LAMMPS divides by (number of dimensions)·N and uses only their
// kinetic components, which breaks the conservation below by O(k_B T ln L/L₀); (1–2) keep it.
// The dilation is about the box centre, coordinates are mapped affinely. "iso" moves the three
// ω̇_d together (one variable of mass 3W; its chain targets k_B T), "aniso" each one on its own
// (the chain targets d k_B T). The conserved quantity is
//   H = K + U + E_chain(atoms) + E_chain(barostat) + Σ_d ½ W ω̇_d² + P_target (V − V₀)   (3)
// (MTK 1994 eq. 2.11); energy_added() returns −(H − K − U). LAMMPS's econserve counts 3k_B T η₁
// of the barostat chain for iso where its dynamics use k_B T; (3) uses k_B T.
// With `lammps_mtk` the MTK terms of a subset of d barostatted dimensions are LAMMPS's,
//   2K/(3N) → Σ_{d barostatted} Σ_i m_i v_i,d² / (d N),   μ = Σ_d ω̇_d / (d N)          (4)
// (identical to (1–2) when all three dimensions are barostatted); fix nphug uses them.
// Tilt factors (LAMMPS fix nh `tri`, `xy`, `xz`, `yz`; Shinoda et al. 2004 eq. 1 with the cell
// matrix h upper triangular, h = [a b c] of geometry::Box): a barostatted tilt t ∈ {xy, xz, yz} is
// one more strain rate ω̇_t of mass W, kicked by its shear pressure,
//   W dω̇_t/dt = V P_t − F_t                                              (5)
// A nonzero target P*_t of a shear pressure (LAMMPS `xy Pstart Pstop Pdamp`, Pstart = Pstop)
// enters as LAMMPS's deviatoric term (FixNH::compute_sigma, compute_deviatoric; Shinoda et al.
// 2004 eq. 1): with the reference cell h₀ and volume V₀ of the stage start,
//   Σ = V₀ h₀⁻¹ (P* − P I) h₀⁻ᵀ,   F = h Σ hᵀ                           (7)
// (P*: the target tensor, P on its diagonal and the shear targets off it), F_t the component of
// F at tilt t, F_d its diagonal component subtracted from the force of (1) too, and the strain
// energy ½ Tr(Σ h hᵀ) joins (3). With zero shear targets F = 0 and (5) is V P_t.
// it couples to the velocities through the upper-triangular ω̇ (LAMMPS nh_v_press; applied with
// the diagonal factors split in two quarter steps around it, as LAMMPS does)
//   v_x ← v_x − ½Δt (ω̇_xy v_y + ω̇_xz v_z),  v_y ← v_y − ½Δt ω̇_yz v_z      (6)
// and moves the cell by ḣ = ω̇ h (LAMMPS FixNH::remap's time-symmetric split, below in
// dilate_triclinic); atoms keep their fractional coordinates. Its kinetic energy ½ W ω̇_t² joins
// (3) and the barostat chain (which then targets the number of all barostatted components, also
// for iso: LAMMPS's pstyle TRICLINIC). A tilted box under a barostat that leaves a tilt alone
// scales that tilt with its second edge (xy with ly, xz and yz with lz: LAMMPS's default
// scalexy/scalexz/scaleyz yes). A tilt that passes 0.6 of its edge (LAMMPS's 0.5 + DELTAFLIP, so
// that a tilt oscillating about one half does not flip back and forth) flips the cell in
// post_integrate (Box::flip_beyond, Simulation::flip_cell; LAMMPS FixNH::pre_exchange, which runs
// at the next neighbour-list rebuild instead, a step or a few later); with `flip` off a tilt past
// half an edge stops the run (LAMMPS `flip no` lets it grow).
// A derived fix may move the thermostat target every step (target_temperature(), called after the
// barostat chain's first half step, as LAMMPS FixNH::compute_temp_target), with the masses kept
// at the temperature the fix was built with or reset by set_reference_temperature().
#include <array>
#include <optional>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/fixes/nose_hoover.hpp"

namespace shockfield::md {

struct NptSettings {
  double temperature = 300;       ///< K
  double damping = 0.1;           ///< τ_T, ps
  double pressure = 0;            ///< bar
  double pressure_damping = 1.0;  ///< τ_P, ps
  std::array<bool, 3> dims{true, true, true};  ///< barostatted dimensions (periodic)
  bool iso = false;               ///< couple the barostatted dimensions (LAMMPS iso)
  int chain = 3;                  ///< length of both chains
  std::optional<int> pressure_chain;  ///< barostat chain length if not `chain` (LAMMPS pchain; 0: none)
  bool lammps_mtk = false;        ///< eq. (4) instead of (1–2) for a subset of dimensions
  std::array<bool, 3> tilt_dims{false, false,
                                false};  ///< barostatted tilt factors xy, xz, yz, eq. (5)
  Vec3 tilt_pressure = Vec3::Zero();  ///< target shear pressures P*_xy, P*_xz, P*_yz, bar, eq. (7)
  bool flip = true;               ///< flip a cell whose tilt passes 0.6 of its edge (LAMMPS flip yes)
};

class FixNoseHooverNpt : public Fix {
 public:
  explicit FixNoseHooverNpt(const NptSettings& settings, std::uint32_t group_bit = 1u);
  std::string name() const override { return "npt"; }
  /// Records V₀ for the P(V − V₀) term of the conserved quantity.
  void setup(Simulation& sim) override;
  void initial_integrate(Simulation& sim) override;
  /// The cell flip, when a tilt passed 0.6 of its edge.
  void post_integrate(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;
  double energy_added() const override;
  FixState state() const override;
  void restore(const FixState& s) override;

 protected:
  /// The thermostat's target temperature for this step (K); NPT's is fixed.
  virtual double target_temperature(const Simulation&) { return settings_.temperature; }
  /// The temperature of the thermostat and barostat masses (and, until the next
  /// target_temperature(), of their targets), K.
  void set_reference_temperature(double temperature);
  /// Both chains' target temperature (K), their masses kept.
  void retarget(double temperature);
  const NptSettings& npt_settings() const { return settings_; }

 private:
  /// ω̇ kick by ½Δt, eq. (1), and the coupling μ of eq. (2).
  void barostat_kick(Simulation& sim);
  /// Barostat chain by ½Δt; scales ω̇.
  void barostat_chain_step(const Simulation& sim);
  /// Atom chain by ½Δt; scales the group's velocities.
  void atom_chain_step(Simulation& sim);
  /// v_d ← v_d e^{−½Δt(ω̇_d + μ)} for the group, with eq. (6) between two quarter steps when a
  /// tilt is barostatted.
  void barostat_velocity_scaling(Simulation& sim) const;
  /// v ← v + ½Δt f/m for the group.
  void velocity_kick(Simulation& sim) const;
  /// Box and all atoms dilated by e^{½Δt ω̇_d} about the box centre.
  void dilate(Simulation& sim);
  /// The same for a tilted cell or barostatted tilts: ḣ = ω̇ h over ½Δt, atoms at fixed
  /// fractional coordinates.
  void dilate_triclinic(Simulation& sim);
  bool tilts_barostatted() const;
  /// F = h Σ hᵀ of eq. (7) in the current cell (bar Å³); zero without shear targets.
  Mat3 deviatoric_force(const geometry::Box& box) const;
  /// The strain energy of eq. (7) in `box`.
  void update_strain_energy(const geometry::Box& box);

  NptSettings settings_;
  std::uint32_t group_bit_;
  NoseHooverChain atom_chain_, barostat_chain_;
  Vec3 omega_dot_ = Vec3::Zero();  ///< 1/ps
  Vec3 tilt_omega_dot_ = Vec3::Zero();  ///< ω̇_t of xy, xz, yz, eq. (5), 1/ps
  double mass_ = 0;                ///< W, eV ps²
  double mu_ = 0;                  ///< eq. (2), 1/ps
  double volume0_ = 0, volume_ = 0;
  bool deviatoric_ = false;        ///< a nonzero shear target, eq. (7)
  Mat3 sigma_ = Mat3::Zero();      ///< Σ of eq. (7), bar Å³ / Å² = bar Å
  double strain_energy_ = 0;       ///< ½ Tr(Σ h hᵀ) of eq. (7) in the current cell, eV
};

}  // namespace shockfield::md
