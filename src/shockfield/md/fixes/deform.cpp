#include "shockfield/md/fixes/deform.hpp"

#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

FixDeform::FixDeform(const Vec3& rate, const geometry::Box& box0, double start_time)
    : rate_(rate), lo0_(box0.lo), hi0_(box0.hi), start_time_(start_time) {}

void FixDeform::end_of_step(Simulation& sim) {
  const double t = sim.time - start_time_;
  geometry::Box& box = sim.box;
  Vec3 scale;
  for (int d = 0; d < 3; ++d) {
    const double centre = 0.5 * (lo0_[d] + hi0_[d]);
    const double length = (hi0_[d] - lo0_[d]) * (1.0 + rate_[d] * t);
    const double old_lo = box.lo[d], old_length = box.hi[d] - box.lo[d];
    box.lo[d] = centre - 0.5 * length;
    box.hi[d] = centre + 0.5 * length;
    scale[d] = length / old_length;
    for (std::size_t i = 0; i < sim.atoms.nlocal; ++i)
      sim.atoms.x[i][d] = box.lo[d] + (sim.atoms.x[i][d] - old_lo) * scale[d];
  }
}

FixState FixDeform::state() const {
  return {{"box_lo0", "Angstrom", {lo0_.x(), lo0_.y(), lo0_.z()}},
          {"box_hi0", "Angstrom", {hi0_.x(), hi0_.y(), hi0_.z()}},
          {"start_time", "ps", {start_time_}}};
}

void FixDeform::restore(const FixState& s) {
  lo0_ = Vec3(fix_state_values(s, name(), "box_lo0", 3).data());
  hi0_ = Vec3(fix_state_values(s, name(), "box_hi0", 3).data());
  start_time_ = fix_state_value(s, name(), "start_time");
}

}  // namespace shockfield::md
