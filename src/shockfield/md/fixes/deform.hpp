#pragma once
// Uniform deformation at constant engineering strain rate (LAMMPS `fix deform ... erate R
// remap x`): at the end of each step every box length is L(t) = L₀(1 + ε̇ t) about the box
// centre, and atom coordinates are mapped affinely with the box. This is the paper's uniform
// dilative / uniaxial strain loading by rescaling of coordinates (Xu et al. 2015, §4.4.1).
#include "shockfield/md/fix.hpp"
#include "shockfield/geometry/box.hpp"

namespace shockfield::md {

class FixDeform : public Fix {
 public:
  /// `rate` per dimension in 1/ps; `start_time` is when the stage began.
  FixDeform(const Vec3& rate, const geometry::Box& box0, double start_time);
  std::string name() const override { return "deform"; }
  void end_of_step(Simulation& sim) override;
  FixState state() const override;
  void restore(const FixState& s) override;

 private:
  Vec3 rate_;
  Vec3 lo0_, hi0_;
  double start_time_;
};

}  // namespace shockfield::md
