#include "shockfield/md/fixes/msst.hpp"

#include <array>
#include <cmath>

#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::ftm2v;
using units::metal::mvv2e;
using units::metal::nktv2p;

namespace {

// The cell volume as LAMMPS's compute_vol forms it (x·y·z lengths).
double cell_volume(const geometry::Box& box) {
  const Vec3 l = box.length();
  return l.x() * l.y() * l.z();
}

// Σ v² over a group, Å²/ps² (Σ_j v_j² of eq. 2).
double velocity_sum(const Atoms& a, std::uint32_t group_bit) {
  double sum = 0;
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit) sum += a.v[i].x() * a.v[i].x() + a.v[i].y() * a.v[i].y() + a.v[i].z() * a.v[i].z();
  return sum;
}

// x' = A − B x over h from x: exact for B·h > 1e-6, else its second-order Taylor form (the
// exact form loses its digits as B → 0). The same threshold as LAMMPS, so the two integrate alike.
double linear_ode_step(double x, double a, double b, double h) {
  if (b * h > 1.0e-6) return (x + a * (std::exp(b * h) - 1.0) / b) * std::exp(-b * h);
  return x + (a - b * x) * h + 0.5 * (b * b * x - a * b) * h * h;
}

// v' = C + D v over h from v (eq. 2 with C = f/m): exact when |D·h| > 1e-6, else second order.
// D depends on the atom only through its mass, so e^{Dh} is computed once per type and component.
struct VelocityStep {
  double d = 0, e = 1;  ///< D and e^{Dh}
  bool exact = false;   ///< |D·h| > 1e-6
  VelocityStep() = default;
  VelocityStep(double d_, double h) : d(d_), exact(std::fabs(h * d_) > 1.0e-6) {
    if (exact) e = std::exp(d * h);
  }
  double operator()(double v, double c, double h) const {
    if (exact) return e * (c + d * v - c / e) / d;
    return v + (c + d * v) * h + 0.5 * (d * d * v + c * d) * h * h;
  }
};

}  // namespace

FixMsst::FixMsst(const MsstSettings& settings, std::uint32_t group_bit)
    : settings_(settings), group_bit_(group_bit) {}

void FixMsst::setup(Simulation& sim) {
  Atoms& a = sim.atoms;
  total_mass_ = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i) total_mass_ += a.mass_of(i);
  lagrangian_position_ = 0;
  steps_done_ = 0;
  averages_ = {};
  const ThermoState t = sim.thermo();
  const int ax = settings_.axis;
  v0_ = settings_.v0.value_or(cell_volume(sim.box));
  p0_ = settings_.p0.value_or(t.pressure_tensor[ax]);
  e0_ = settings_.e0.value_or(t.potential + t.kinetic);
  omega_ = 0;
  // Bias the start towards compression: a fraction tscale of the kinetic energy (2K over all
  // atoms, LAMMPS's ke_temp) becomes cell motion, Q V̇²/(2M) = tscale·K.
  const double twice_ke = 2.0 * t.kinetic;
  if (twice_ke > 0 && settings_.tscale > 0) {
    omega_ = -std::sqrt(settings_.tscale * total_mass_ / settings_.q * twice_ke / mvv2e);
    const double scale = std::sqrt(1.0 - settings_.tscale);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < a.nlocal; ++i)
      if (a.mask[i] & group_bit_) a.v[i] *= scale;
  }
  volume_ = cell_volume(sim.box);
  vsum_ = velocity_sum(a, group_bit_);
  h_start_ = sim.kinetic_energy() + sim.forces.energy + scalar();
}

void FixMsst::cell_half_step(const Simulation& sim) {
  const double p_axis = sim.thermo().pressure_tensor[settings_.axis];
  const double vol = cell_volume(sim.box);
  const double us = settings_.shock_speed, m = total_mass_, q = settings_.q;
  // Eq. (1): V̈ = A − B V̇ with A from the distance to the Rayleigh line p₀ + ρ₀U_s²(1 − V/V₀).
  const double p_rayleigh = nktv2p * mvv2e * us * us * m * (v0_ - vol) / (v0_ * v0_);  // bar, minus p₀
  double accel = m * (p_axis - p0_ - p_rayleigh) / (q * nktv2p * mvv2e);
  const double damping = m * settings_.mu / (q * vol);
  // LAMMPS's guard against a cell that expands past V₀ and keeps going: the push is reversed.
  if (vol > v0_ && accel > 0.0) accel = -accel;
  omega_ = linear_ode_step(omega_, accel, damping, 0.5 * sim.dt);
}

void FixMsst::velocity_half_step(Simulation& sim, double vsum) const {
  Atoms& a = sim.atoms;
  const double h = 0.5 * sim.dt, vol = cell_volume(sim.box);
  const int ax = settings_.axis;
  const double viscous = settings_.mu * omega_ * omega_;  // numerator of eq. (2)'s first term
  const double strain = 2.0 * omega_ / vol;
  std::vector<std::array<VelocityStep, 3>> steps(a.mass.size());
  for (std::size_t t = 0; t < a.mass.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      double d = viscous / (vsum * a.mass[t] * vol);
      if (k == ax) d -= strain;
      steps[t][k] = VelocityStep(d, h);
    }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (!(a.mask[i] & group_bit_)) continue;
    const double mass = a.mass_of(i);
    const auto& step = steps[static_cast<std::size_t>(a.type[i])];
    for (int k = 0; k < 3; ++k) a.v[i][k] = step[k](a.v[i][k], a.f[i][k] * ftm2v / mass, h);
  }
}

void FixMsst::remap(Simulation& sim, double dilation) {
  geometry::Box& box = sim.box;
  Atoms& a = sim.atoms;
  const int ax = settings_.axis;
  // Fractional coordinates in the old cell, the cell rescaled about its centre, back to
  // Cartesian in the new one (LAMMPS x2lamda/lamda2x: every coordinate makes the round trip).
  const Vec3 lo_old = box.lo, len_old = box.length();
  const Vec3 inv_old(1.0 / len_old.x(), 1.0 / len_old.y(), 1.0 / len_old.z());
  const double centre = 0.5 * (box.lo[ax] + box.hi[ax]);
  box.lo[ax] = (box.lo[ax] - centre) * dilation + centre;
  box.hi[ax] = (box.hi[ax] - centre) * dilation + centre;
  const Vec3 lo_new = box.lo, len_new = box.length();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    for (int d = 0; d < 3; ++d) a.x[i][d] = len_new[d] * (inv_old[d] * (a.x[i][d] - lo_old[d])) + lo_new[d];
    a.v[i][ax] *= dilation;
  }
}

void FixMsst::initial_integrate(Simulation& sim) {
  Atoms& a = sim.atoms;
  cell_half_step(sim);
  // Eq. (2) needs Σv² at the half step: propagate once with the current sum to estimate it,
  // restore the velocities, and propagate with the estimate.
  const std::vector<Vec3> v_old(a.v.begin(), a.v.begin() + static_cast<std::ptrdiff_t>(a.nlocal));
  velocity_half_step(sim, velocity_sum(a, group_bit_));
  vsum_ = velocity_sum(a, group_bit_);
  std::copy(v_old.begin(), v_old.end(), a.v.begin());
  velocity_half_step(sim, vsum_);
  // Volume half step, drift, volume half step.
  const double vol = cell_volume(sim.box);
  const double vol1 = vol + omega_ * 0.5 * sim.dt;
  remap(sim, vol1 / vol);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit_) a.x[i] += sim.dt * a.v[i];
  const double vol2 = vol1 + omega_ * 0.5 * sim.dt;
  remap(sim, vol2 / vol1);
  volume_ = cell_volume(sim.box);
}

void FixMsst::final_integrate(Simulation& sim) {
  velocity_half_step(sim, vsum_);
  vsum_ = velocity_sum(sim.atoms, group_bit_);
  cell_half_step(sim);
  volume_ = cell_volume(sim.box);
  lagrangian_position_ -= settings_.shock_speed * volume_ / v0_ * sim.dt;
}

void FixMsst::end_of_step(Simulation& sim) {
  ++steps_done_;
  if (2 * steps_done_ <= settings_.stage_steps) return;
  const ThermoState t = sim.thermo();
  averages_.samples += 1;
  averages_.up += settings_.shock_speed * (1.0 - t.volume / v0_);
  averages_.pressure_axis += t.pressure_tensor[settings_.axis];
  averages_.volume += t.volume;
  averages_.temperature += t.temperature;
}

double FixMsst::scalar() const {
  const double us = settings_.shock_speed, strain = 1.0 - volume_ / v0_;
  return settings_.q * omega_ * omega_ / (2.0 * total_mass_) * mvv2e -
         0.5 * total_mass_ * us * us * strain * strain * mvv2e - p0_ * (v0_ - volume_) / nktv2p;
}

MsstQuantities FixMsst::quantities(const Simulation& sim) const {
  const ThermoState t = sim.thermo();
  MsstQuantities q;
  q.energy = scalar();
  q.volume = cell_volume(sim.box);
  q.pressure_axis = t.pressure_tensor[settings_.axis];
  const double dof = std::max(3.0 * static_cast<double>(sim.atoms.nlocal) - 3.0, 1.0);
  const double e = t.potential + t.kinetic;
  q.dhugoniot = (0.5 * (q.pressure_axis + p0_) * (v0_ - q.volume) / nktv2p + e0_ - e) / (dof * boltz);
  const double us = settings_.shock_speed;
  q.drayleigh = q.pressure_axis - p0_ - total_mass_ * us * us * mvv2e * (1.0 - q.volume / v0_) * nktv2p / v0_;
  q.lagrangian_speed = us * (1.0 - q.volume / v0_);
  q.lagrangian_position = lagrangian_position_;
  return q;
}

FixState FixMsst::state() const {
  return {{"volume_rate", "Angstrom^3/ps", {omega_}},
          {"p0", "bar", {p0_}},
          {"v0", "Angstrom^3", {v0_}},
          {"e0", "eV", {e0_}},
          {"total_mass", "g/mol", {total_mass_}},
          {"volume", "Angstrom^3", {volume_}},
          {"velocity_square_sum", "Angstrom^2/ps^2", {vsum_}},
          {"lagrangian_position", "Angstrom", {lagrangian_position_}},
          {"conserved_at_start", "eV", {h_start_}},
          {"steps_done", "1", {static_cast<double>(steps_done_)}},
          {"average_samples", "1", {averages_.samples}},
          {"sum_up", "Angstrom/ps", {averages_.up}},
          {"sum_pressure_axis", "bar", {averages_.pressure_axis}},
          {"sum_volume", "Angstrom^3", {averages_.volume}},
          {"sum_temperature", "K", {averages_.temperature}}};
}

void FixMsst::restore(const FixState& s) {
  const auto value = [&](const char* key) { return fix_state_value(s, name(), key); };
  omega_ = value("volume_rate");
  p0_ = value("p0");
  v0_ = value("v0");
  e0_ = value("e0");
  total_mass_ = value("total_mass");
  volume_ = value("volume");
  vsum_ = value("velocity_square_sum");
  lagrangian_position_ = value("lagrangian_position");
  h_start_ = value("conserved_at_start");
  steps_done_ = static_cast<std::int64_t>(value("steps_done"));
  averages_ = {value("average_samples"), value("sum_up"), value("sum_pressure_axis"), value("sum_volume"),
               value("sum_temperature")};
}

}  // namespace shockfield::md
