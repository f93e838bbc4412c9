#include "shockfield/md/fixes/piston.hpp"

#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

FixPiston::FixPiston(int axis, int side, double speed, double position, double start_time)
    : axis_(axis), side_(side), speed_(speed), position_(position), start_time_(start_time) {}

void FixPiston::restore(const FixState& s) {
  work_ = fix_state_value(s, name(), "work");
  position_ = fix_state_value(s, name(), "position");
  start_time_ = fix_state_value(s, name(), "start_time");
}

void FixPiston::post_integrate(Simulation& sim) {
  Atoms& a = sim.atoms;
  // post_integrate runs before the clock advances: the drift ends at time + dt.
  const double w = wall(sim.time + sim.dt);
  const double up = side_ * speed_;
  double work = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    double& x = a.x[i][axis_];
    if (side_ * (x - w) >= 0) continue;
    double& v = a.v[i][axis_];
    const double before = v * v;
    x = 2.0 * w - x;
    v = 2.0 * up - v;
    work += 0.5 * a.mass_of(i) * (v * v - before);
  }
  work_ += work * units::metal::mvv2e;
}

}  // namespace shockfield::md
