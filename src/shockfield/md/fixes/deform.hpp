#pragma once
// Uniform deformation at constant engineering strain rate (LAMMPS `fix deform ... erate R
// remap x`): at the end of each step every box length is L(t) = L₀(1 + ε̇ t) about the box
// centre, and atom coordinates are mapped affinely with the box. This is the paper's uniform
// dilative / uniaxial strain loading by rescaling of coordinates (Xu et al. 2015, §4.4.1).
// Tilt rates (LAMMPS `fix deform ... xy erate R xz erate R yz erate R remap x`): each tilt factor
// with a nonzero rate is T(t) = T₀ + L₀ ε̇ t with L₀ the start length of the box along the shear's
// gradient (y for xy, z for xz and yz), shifted by whole edges (lx for xy and xz, ly for yz) to
// the value nearest the current tilt (LAMMPS FixDeform::end_of_step, so T keeps growing across a
// flip); a tilt of rate zero stays as it is. Atoms keep their fractional coordinates (LAMMPS
// x2lamda, new box, lamda2x). A tilt past half its edge flips the cell (LAMMPS `flip yes`,
// Box::flip_beyond(0.5)) at the next step, after the positions' update and before the forces
// (LAMMPS's pre_exchange); with flips off (`flip no`) the run stops there instead.
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/fix.hpp"

namespace shockfield::md {

class FixDeform : public Fix {
 public:
  /// `rate` per dimension and `tilt_rate` per tilt factor (xy, xz, yz) in 1/ps; `start_time` is
  /// when the stage began; `flip`: flip the cell (else stop) when a tilt passes half an edge.
  FixDeform(const Vec3& rate, const Vec3& tilt_rate, const geometry::Box& box0, double start_time,
            bool flip = true);
  std::string name() const override { return "deform"; }
  /// A flip found at the end of the last step.
  void post_integrate(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  FixState state() const override;
  void restore(const FixState& s) override;

 private:
  void end_of_step_triclinic(Simulation& sim);

  Vec3 rate_, tilt_rate_;
  Vec3 lo0_, hi0_, tilt0_;
  double start_time_;
  bool flip_;
  geometry::CellFlip pending_flip_;
};

}  // namespace shockfield::md
