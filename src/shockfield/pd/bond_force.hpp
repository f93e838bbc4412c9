#pragma once
// The bond loop for ordinary force laws (bond_models.hpp), written once and instantiated for PMB
// and LPS. Each point walks its own CSR family (every bond is stored from both ends, as in
// LAMMPS's fix PERI_NEIGH), so a thread writes only its own points: no atomics and results that
// do not depend on the thread count. With `contact` the short-range contact force of LAMMPS's
// PERI package (contact.hpp) is added to every point's bond force.
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "shockfield/pd/bond_models.hpp"
#include "shockfield/pd/bond_stretch.hpp"
#include "shockfield/pd/contact.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/force_model.hpp"
#include "shockfield/pd/influence.hpp"
#include "shockfield/pd/model_state.hpp"

namespace shockfield::pd {

template <class Model>
class BondForce final : public ForceModel {
 public:
  /// `contact`: add the short-range contact force of LAMMPS's PERI package (contact.hpp) with the
  /// model's contact_micromodulus.
  BondForce(const PointCloud& cloud, const Family& family, Model model, Influence influence,
            CriticalStretch damage, bool contact = false);

  void compute(const Kinematics& k, std::vector<Vec3>& force_density) override;
  double stable_step(const std::vector<double>& density) const override;
  std::vector<double> damage() const override;
  std::string name() const override;

  /// Breaks the bonds flagged 1 in `cut` (one flag per bond of the family: a pre-crack,
  /// precrack.hpp) before the first step; they count in the damage like any broken bond.
  void break_bonds(const std::vector<unsigned char>& cut);

  /// On MPI ranks (pd/decomposition.hpp) the body holds ghosts, whose families are cut short:
  /// `forward` copies every owned point's value of a per-point array to its ghosts. It is applied
  /// to the weighted volumes now, to the critical stretches before each evaluation and to the
  /// dilatations once computed, so that what a bond of an owned point reads of a ghost is its owner's.
  void set_ghost_forward(std::function<void(std::vector<double>&)> forward);

  const std::vector<double>& weighted_volume() const { return weighted_volume_; }
  const std::vector<double>& dilatation() const { return theta_; }
  std::size_t intact_bonds() const;
  /// Elastic energy of the intact bonds plus the contact energy at positions y [J, per unit of the
  /// missing dimensions]: PMB Σ_i V_i Σ_j ¼·c·s²·r0·V_j·β; LPS Σ_i V_i [κ_d θ_i²/2 + Σ_j B_d ω
  /// (e − θ_i r0/d)² V_j β/(2m_i)] (bond_models.hpp). The dilatations are those of y.
  double potential_energy(const std::vector<Vec3>& y);
  /// The bonds' strain energy density W_i of every point at y [J/m^dim] (no contact).
  std::vector<double> energy_density(const std::vector<Vec3>& y);
  /// The contact force, if on.
  ShortRangeContact* contact() { return contact_ ? &*contact_ : nullptr; }

  /// The damage state for checkpoints: `bond_intact` (1/0 for every bond entry of the family, each
  /// bond stored from both ends) and `critical_stretch` (every point's s0 of the next step). The
  /// dilatations are recomputed from the positions at each force evaluation, so this is all a
  /// resume needs to continue bitwise.
  ModelState saved_state() const;
  /// Takes back saved_state() (InputError naming the array on a missing one or a size mismatch).
  void restore_state(const ModelState& state);

 private:
  BondTerms terms(std::size_t i, int b, double e) const;
  void compute_dilatation(const std::vector<Vec3>& y);
  /// per_point(i, bonds) for every point, threaded, with i's bonds measured at y (bond_stretch.hpp).
  template <class PerPoint>
  void for_each_point_measured(const std::vector<Vec3>& y, PerPoint&& per_point);
  /// The force and damage loop over every point's bonds, with or without critical-stretch damage.
  template <bool kDamage>
  void bond_loop(const std::vector<Vec3>& y, std::vector<Vec3>& force_density);
  /// bonds.pull[k] = t·V_j·β/r of point i's k-th bond (0 at r = 0), from its measured bonds.
  void bond_pull(std::size_t i, BondStretches& bonds) const;

  const PointCloud& cloud_;
  const Family& family_;
  Model model_;
  CriticalStretch damage_law_;
  std::vector<double> omega_;            // per bond
  std::vector<double> bond_constant_;    // per bond, LinearInStretch models: k_b = (c·V_j)·β
  std::vector<double> weighted_volume_;  // m_i = Σ ω r0² V β (fixed, LAMMPS wvolume)
  std::vector<double> theta_;
  std::vector<unsigned char> intact_;    // per bond
  std::vector<double> s0_, s0_new_;
  std::optional<ShortRangeContact> contact_;
  std::function<void(std::vector<double>&)> forward_;
};

using PmbForce = BondForce<PmbModel>;
using LpsForce = BondForce<LpsModel>;

}  // namespace shockfield::pd
