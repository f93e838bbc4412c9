#pragma once
// Momentum-mirror piston (LAMMPS `fix wall/piston`): a flat wall normal to `axis` starts at
// `position` and moves into the material at constant speed u_p. After the drift, every atom
// found behind the wall is reflected off it: x ← 2w − x, v ← 2u_p − v along the axis. The
// reflected atoms move at up to 2u_p − v, so the material ahead is driven at u_p and a shock
// runs ahead of the wall (Xu et al. 2015, §4.4: shock loading of EAM metals). Tracks the work done by the
// wall for the conserved-quantity column.
#include "shockfield/md/fix.hpp"

namespace shockfield::md {

class FixPiston : public Fix {
 public:
  /// `side` = +1 pushes towards +axis from the low face, −1 towards −axis from the high face.
  FixPiston(int axis, int side, double speed, double position, double start_time);
  std::string name() const override { return "piston"; }
  void post_integrate(Simulation& sim) override;
  double energy_added() const override { return work_; }
  FixState state() const override {
    return {{"work", "eV", {work_}}, {"position", "Angstrom", {position_}}, {"start_time", "ps", {start_time_}}};
  }
  void restore(const FixState& s) override;
  int axis() const { return axis_; }
  int side() const { return side_; }
  double speed() const { return speed_; }
  double start_time() const { return start_time_; }
  double start_position() const { return position_; }
  /// Wall position at time t.
  double wall(double t) const { return position_ + side_ * speed_ * (t - start_time_); }

 private:
  int axis_, side_;
  double speed_, position_, start_time_;
  double work_ = 0;
};

}  // namespace shockfield::md
