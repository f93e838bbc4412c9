#pragma once
// Uniform deformation at constant engineering strain rate (LAMMPS `fix deform ... erate R
// remap x`): at the end of each step every box length is L(t) = L₀(1 + ε̇ t) about the box
// centre, and atom coordinates are mapped affinely with the box. This is the paper's uniform
// dilative / uniaxial strain loading by rescaling of coordinates (Xu et al. 2015, §4.4.1).
// Tilt rates (LAMMPS `fix deform ... xy erate R xz erate R yz erate R remap x`): each tilt factor
// is T(t) = T₀ + L₀ ε̇ t with L₀ the start length of the box along the shear's gradient (y for
// xy, z for xz and yz), and atoms keep their fractional coordinates (LAMMPS x2lamda, new box,
// lamda2x). LAMMPS flips a cell whose tilt passes half an edge; this fix stops the run there.
#include "shockfield/md/fix.hpp"
#include "shockfield/geometry/box.hpp"

namespace shockfield::md {

class FixDeform : public Fix {
 public:
  /// `rate` per dimension and `tilt_rate` per tilt factor (xy, xz, yz) in 1/ps; `start_time` is
  /// when the stage began.
  FixDeform(const Vec3& rate, const Vec3& tilt_rate, const geometry::Box& box0, double start_time);
  std::string name() const override { return "deform"; }
  void end_of_step(Simulation& sim) override;
  FixState state() const override;
  void restore(const FixState& s) override;

 private:
  Vec3 rate_, tilt_rate_;
  Vec3 lo0_, hi0_, tilt0_;
  double start_time_;
};

}  // namespace shockfield::md
