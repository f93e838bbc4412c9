#include "shockfield/md/fixes/deform.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

FixDeform::FixDeform(const Vec3& rate, const Vec3& tilt_rate, const geometry::Box& box0, double start_time,
                     bool flip)
    : rate_(rate), tilt_rate_(tilt_rate), lo0_(box0.lo), hi0_(box0.hi), tilt0_(box0.tilt), start_time_(start_time),
      flip_(flip) {}

void FixDeform::post_integrate(Simulation& sim) {
  if (!pending_flip_.any()) return;
  sim.flip_cell(pending_flip_);
  pending_flip_ = {};
}

// LAMMPS FixDeform::end_of_step, triclinic: the new lengths, each tilt's target shifted by whole
// edges of the new cell to the one nearest the current tilt ratio, the atoms remapped, a flip
// scheduled for the next step when a tilt passed half its edge.
void FixDeform::end_of_step_triclinic(Simulation& sim) {
  const double t = sim.time - start_time_;
  geometry::Box& box = sim.box;
  const geometry::Box old = box;
  const Vec3 length0 = hi0_ - lo0_;
  for (int d = 0; d < 3; ++d) {
    const double centre = 0.5 * (lo0_[d] + hi0_[d]), length = length0[d] * (1.0 + rate_[d] * t);
    box.lo[d] = centre - 0.5 * length;
    box.hi[d] = centre + 0.5 * length;
  }
  const Vec3 gradient_length(length0.y(), length0.z(), length0.z());  // xy: y; xz, yz: z
  static constexpr std::array<int, 3> edge_of{0, 0, 1};            // xy, xz: lx; yz: ly
  for (int k = 0; k < 3; ++k) {
    if (tilt_rate_[k] == 0) continue;
    double target = tilt0_[k] + t * tilt_rate_[k] * gradient_length[k];
    const double edge = box.length()[edge_of[k]], current = old.tilt[k] / old.length()[edge_of[k]];
    while (target / edge - current > 0.0) target -= edge;
    while (target / edge - current < 0.0) target += edge;
    if (std::abs(target / edge - 1.0 - current) < std::abs(target / edge - current)) target -= edge;
    box.tilt[k] = target;
  }
  if (flip_) {
    pending_flip_ = box.flip_beyond(0.5);
  } else {
    try {
      box.check_tilt(fmt::format("step {}: deform_tilt_rate with flip = false (LAMMPS flip no)", sim.step));
    } catch (const InputError& e) {
      throw RunError(e.what());
    }
  }
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i) sim.atoms.x[i] = box.from_fractional(old.to_fractional(sim.atoms.x[i]));
}

void FixDeform::end_of_step(Simulation& sim) {
  if (sim.box.triclinic() || tilt_rate_ != Vec3::Zero()) {
    end_of_step_triclinic(sim);
    return;
  }
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
  FixState s{{"box_lo0", "Angstrom", {lo0_.x(), lo0_.y(), lo0_.z()}},
              {"box_hi0", "Angstrom", {hi0_.x(), hi0_.y(), hi0_.z()}},
              {"start_time", "ps", {start_time_}}};
  if (tilt0_ != Vec3::Zero()) s.push_back({"box_tilt0", "Angstrom", {tilt0_.x(), tilt0_.y(), tilt0_.z()}});
  if (pending_flip_.any())  // found at the end of the step the checkpoint follows
    s.push_back({"pending_flip", "1", {1.0 * pending_flip_.m, 1.0 * pending_flip_.n, 1.0 * pending_flip_.p}});
  return s;
}

void FixDeform::restore(const FixState& s) {
  lo0_ = Vec3(fix_state_values(s, name(), "box_lo0", 3).data());
  hi0_ = Vec3(fix_state_values(s, name(), "box_hi0", 3).data());
  start_time_ = fix_state_value(s, name(), "start_time");
  auto has = [&s](const char* item_name) {
    return std::any_of(s.begin(), s.end(), [item_name](const FixStateItem& item) { return item.name == item_name; });
  };
  tilt0_ = has("box_tilt0") ? Vec3(fix_state_values(s, name(), "box_tilt0", 3).data()) : Vec3::Zero();
  pending_flip_ = {};
  if (has("pending_flip")) {
    const auto& f = fix_state_values(s, name(), "pending_flip", 3);
    pending_flip_ = {static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2])};
  }
}

}  // namespace shockfield::md
