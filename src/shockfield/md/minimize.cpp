#include "shockfield/md/minimize.hpp"

#include <cmath>

#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::ftm2v;
using units::metal::nktv2p;

namespace {

// FIRE parameters (Bitzek et al. 2006, Table I).
constexpr int kDelay = 5;
constexpr double kIncrease = 1.1, kDecrease = 0.5, kAlpha0 = 0.1, kAlphaShrink = 0.99;

// Box-length generalised forces (eV/Å) from the current virial; kinetic part excluded (a
// minimisation has no temperature).
Vec3 box_forces(const Simulation& sim, double target) {
  const double v = sim.box.volume();
  Vec3 f;
  for (int d = 0; d < 3; ++d) {
    const double p = sim.forces.virial[d] / v * nktv2p;
    f[d] = (p - target) / nktv2p * v / sim.box.length()[d];
  }
  return f;
}

void scale_box(Simulation& sim, int d, double new_length) {
  const double s = new_length / sim.box.length()[d];
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i)
    sim.atoms.x[i][d] = sim.box.lo[d] + (sim.atoms.x[i][d] - sim.box.lo[d]) * s;
  sim.box.hi[d] = sim.box.lo[d] + new_length;
}

// Forces of the atoms outside the moving group are zero: they neither move nor count in max |f|.
void hold_frozen(Atoms& a, std::uint32_t group) {
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (!(a.mask[i] & group)) a.f[i].setZero();
}

}  // namespace

MinimizeResult minimize_fire(Simulation& sim, const MinimizeSettings& s) {
  Atoms& a = sim.atoms;
  sim.setup(false);
  hold_frozen(a, s.group);
  double total_mass = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i) total_mass += a.mass_of(i);
  // A box length drags all atoms; a mass of a tenth of the crystal keeps its motion comparable
  // to the atoms' (a convergence-speed choice only: minima do not depend on it).
  const double box_mass = std::max(0.1 * total_mass, 1.0);
  std::vector<Vec3> v(a.nlocal, Vec3::Zero());
  Vec3 box_v = Vec3::Zero();
  double dt = sim.dt, alpha = kAlpha0;
  int since_negative = 0;
  MinimizeResult r;
  for (r.iterations = 0; r.iterations < s.max_iterations; ++r.iterations) {
    const Vec3 fbox = box_forces(sim, s.target_pressure);
    double fmax2 = 0;
    for (std::size_t i = 0; i < a.nlocal; ++i) fmax2 = std::max(fmax2, a.f[i].squaredNorm());
    r.max_force = std::sqrt(fmax2);
    bool pressure_ok = true;
    for (int d = 0; d < 3; ++d) {
      r.pressure[d] = sim.forces.virial[d] / sim.box.volume() * nktv2p;
      if (s.relax_box[d] && std::abs(r.pressure[d] - s.target_pressure) > s.pressure_tolerance) pressure_ok = false;
    }
    r.energy = sim.forces.energy;
    if (r.max_force < s.force_tolerance && pressure_ok) {
      r.converged = true;
      r.reason = "force and pressure tolerances met";
      return r;
    }
    if (stop_requested()) {
      r.reason = "stopped by signal";
      return r;
    }
    // FIRE: power P = F·v over all degrees of freedom.
    double power = 0, vnorm2 = 0, fnorm2 = 0;
    for (std::size_t i = 0; i < a.nlocal; ++i) {
      power += a.f[i].dot(v[i]);
      vnorm2 += v[i].squaredNorm();
      fnorm2 += a.f[i].squaredNorm();
    }
    for (int d = 0; d < 3; ++d) {
      if (!s.relax_box[d]) continue;
      power += fbox[d] * box_v[d];
      vnorm2 += box_v[d] * box_v[d];
      fnorm2 += fbox[d] * fbox[d];
    }
    if (power > 0) {
      const double mix = fnorm2 > 0 ? alpha * std::sqrt(vnorm2 / fnorm2) : 0.0;
      for (std::size_t i = 0; i < a.nlocal; ++i) v[i] = (1 - alpha) * v[i] + mix * a.f[i];
      for (int d = 0; d < 3; ++d) box_v[d] = (1 - alpha) * box_v[d] + mix * fbox[d];
      if (++since_negative > kDelay) {
        dt = std::min(dt * kIncrease, s.max_timestep_factor * sim.dt);
        alpha *= kAlphaShrink;
      }
    } else {
      since_negative = 0;
      dt *= kDecrease;
      alpha = kAlpha0;
      for (auto& vi : v) vi.setZero();
      box_v.setZero();
    }
    // Semi-implicit Euler step.
    for (std::size_t i = 0; i < a.nlocal; ++i) {
      v[i] += dt * ftm2v / a.mass_of(i) * a.f[i];
      a.x[i] += dt * v[i];
    }
    for (int d = 0; d < 3; ++d) {
      if (!s.relax_box[d]) continue;
      box_v[d] += dt * ftm2v / box_mass * fbox[d];
      scale_box(sim, d, sim.box.length()[d] + dt * box_v[d]);
    }
    sim.compute_forces(false);
    hold_frozen(a, s.group);
  }
  r.reason = "maximum number of iterations reached";
  return r;
}

}  // namespace shockfield::md
