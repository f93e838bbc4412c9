#include "shockfield/md/fixes/deform.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

FixDeform::FixDeform(const Vec3& rate, const Vec3& tilt_rate, const geometry::Box& box0, double start_time)
    : rate_(rate), tilt_rate_(tilt_rate), lo0_(box0.lo), hi0_(box0.hi), tilt0_(box0.tilt), start_time_(start_time) {}

void FixDeform::end_of_step(Simulation& sim) {
  const double t = sim.time - start_time_;
  geometry::Box& box = sim.box;
  if (box.triclinic() || tilt_rate_ != Vec3::Zero()) {  // LAMMPS FixDeform::end_of_step, triclinic
    const geometry::Box old = box;
    const Vec3 length0 = hi0_ - lo0_;
    for (int d = 0; d < 3; ++d) {
      const double centre = 0.5 * (lo0_[d] + hi0_[d]), length = length0[d] * (1.0 + rate_[d] * t);
      box.lo[d] = centre - 0.5 * length;
      box.hi[d] = centre + 0.5 * length;
    }
    const Vec3 gradient_length(length0.y(), length0.z(), length0.z());  // xy: y; xz, yz: z
    box.tilt = tilt0_ + t * tilt_rate_.cwiseProduct(gradient_length);
    try {
      box.check_tilt(fmt::format("step {}: deform_tilt_rate (LAMMPS would flip the cell here; shockfield does not)", sim.step));
    } catch (const InputError& e) {
      throw RunError(e.what());
    }
    for (std::size_t i = 0; i < sim.atoms.nlocal; ++i) sim.atoms.x[i] = box.from_fractional(old.to_fractional(sim.atoms.x[i]));
    return;
  }
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
  FixState s{{"box_lo0", "Angstrom", {lo0_.x(), lo0_.y(), lo0_.z()}},
              {"box_hi0", "Angstrom", {hi0_.x(), hi0_.y(), hi0_.z()}},
              {"start_time", "ps", {start_time_}}};
  if (tilt0_ != Vec3::Zero()) s.push_back({"box_tilt0", "Angstrom", {tilt0_.x(), tilt0_.y(), tilt0_.z()}});
  return s;
}

void FixDeform::restore(const FixState& s) {
  lo0_ = Vec3(fix_state_values(s, name(), "box_lo0", 3).data());
  hi0_ = Vec3(fix_state_values(s, name(), "box_hi0", 3).data());
  start_time_ = fix_state_value(s, name(), "start_time");
  const bool tilted = std::any_of(s.begin(), s.end(), [](const FixStateItem& item) { return item.name == "box_tilt0"; });
  tilt0_ = tilted ? Vec3(fix_state_values(s, name(), "box_tilt0", 3).data()) : Vec3::Zero();
}

}  // namespace shockfield::md
