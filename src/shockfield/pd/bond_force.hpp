#pragma once
// The bond loop for ordinary force laws (bond_models.hpp), written once and instantiated for PMB
// and LPS. Each point walks its own CSR family (every bond is stored from both ends, as in
// LAMMPS's fix PERI_NEIGH), so a thread writes only its own points: no atomics and results that
// do not depend on the thread count.
#include <limits>
#include <memory>
#include <vector>

#include "shockfield/pd/bond_models.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/force_model.hpp"
#include "shockfield/pd/influence.hpp"

namespace shockfield::pd {

template <class Model>
class BondForce final : public ForceModel {
 public:
  BondForce(const PointCloud& cloud, const Family& family, Model model, Influence influence,
            CriticalStretch damage);

  void compute(const Kinematics& k, std::vector<Vec3>& force_density) override;
  double stable_step(const std::vector<double>& density) const override;
  std::vector<double> damage() const override;
  std::string name() const override;

  const std::vector<double>& weighted_volume() const { return weighted_volume_; }
  const std::vector<double>& dilatation() const { return theta_; }
  std::size_t intact_bonds() const;

  /// The damage state for checkpoints: the intact flag of every bond (1/0) then every point's
  /// critical stretch s0 of the next step. The dilatations are recomputed from the positions at
  /// each force evaluation, so this is all a resume needs to continue bitwise.
  std::vector<double> saved_state() const;
  /// Takes back saved_state() (InputError on a size mismatch).
  void restore_state(const std::vector<double>& data);

 private:
  BondTerms terms(std::size_t i, int b, double e) const;
  void compute_dilatation(const std::vector<Vec3>& y);

  const PointCloud& cloud_;
  const Family& family_;
  Model model_;
  CriticalStretch damage_law_;
  std::vector<double> omega_;            // per bond
  std::vector<double> weighted_volume_;  // m_i = Σ ω r0² V β (fixed, LAMMPS wvolume)
  std::vector<double> theta_;
  std::vector<unsigned char> intact_;    // per bond
  std::vector<double> s0_, s0_new_;
};

using PmbForce = BondForce<PmbModel>;
using LpsForce = BondForce<LpsModel>;

}  // namespace shockfield::pd
