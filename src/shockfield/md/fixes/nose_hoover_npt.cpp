#include "shockfield/md/fixes/nose_hoover_npt.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <Eigen/LU>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/velocity.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::nktv2p;

FixNoseHooverNpt::FixNoseHooverNpt(const NptSettings& settings, std::uint32_t group_bit)
    : settings_(settings), group_bit_(group_bit),
      atom_chain_(settings.chain, settings.temperature, settings.damping),
      barostat_chain_(settings.pressure_chain.value_or(settings.chain), settings.temperature,
                      settings.pressure_damping) {}

void FixNoseHooverNpt::set_reference_temperature(double temperature) {
  settings_.temperature = temperature;
  atom_chain_ = NoseHooverChain(settings_.chain, temperature, settings_.damping);
  barostat_chain_ = NoseHooverChain(settings_.pressure_chain.value_or(settings_.chain), temperature,
                                    settings_.pressure_damping);
}

void FixNoseHooverNpt::setup(Simulation& sim) {
  volume0_ = volume_ = sim.box.volume();
  deviatoric_ = settings_.tilt_pressure != Vec3::Zero();
  if (!deviatoric_) return;
  // Σ of eq. (7): the target minus its hydrostatic part P I has only the shear targets.
  const Vec3& t = settings_.tilt_pressure;  // xy, xz, yz
  Mat3 deviator;
  deviator << 0, t[0], t[1], t[0], 0, t[2], t[1], t[2], 0;
  const Mat3 h0_inverse = sim.box.cell().inverse();
  sigma_ = volume0_ * h0_inverse * deviator * h0_inverse.transpose();
  update_strain_energy(sim.box);
}

void FixNoseHooverNpt::update_strain_energy(const geometry::Box& box) {
  if (!deviatoric_) return;
  // ½ Tr(Σ h hᵀ) of eq. (7) (LAMMPS FixNH::compute_strain_energy), eV.
  const Mat3 h = box.cell();
  strain_energy_ = 0.5 * (sigma_ * h * h.transpose()).trace() / nktv2p;
}

Mat3 FixNoseHooverNpt::deviatoric_force(const geometry::Box& box) const {
  const Mat3 h = box.cell();
  return h * sigma_ * h.transpose();
}

void FixNoseHooverNpt::retarget(double temperature) {
  atom_chain_.retarget(temperature);
  barostat_chain_.retarget(temperature);
}

void FixNoseHooverNpt::initial_integrate(Simulation& sim) {
  const double omega_p = 1.0 / settings_.pressure_damping;
  mass_ = (static_cast<double>(sim.atoms.nlocal) + 1.0) * boltz * settings_.temperature / (omega_p * omega_p);
  barostat_chain_step(sim);
  retarget(target_temperature(sim));
  atom_chain_step(sim);
  barostat_kick(sim);
  barostat_velocity_scaling(sim);
  velocity_kick(sim);
  dilate(sim);
  Atoms& a = sim.atoms;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit_) a.x[i] += sim.dt * a.v[i];
  dilate(sim);
}

void FixNoseHooverNpt::post_integrate(Simulation& sim) {
  if (!settings_.flip || !sim.box.triclinic()) return;
  const geometry::CellFlip flip = sim.box.flip_beyond(0.6);  // LAMMPS: 0.5 + DELTAFLIP
  if (flip.any()) sim.flip_cell(flip);
}

void FixNoseHooverNpt::final_integrate(Simulation& sim) {
  velocity_kick(sim);
  barostat_velocity_scaling(sim);
  barostat_kick(sim);
  atom_chain_step(sim);
  barostat_chain_step(sim);
  check_extended_energy(sim, name().c_str(), -energy_added(), atom_chain_.degrees_of_freedom(), settings_.temperature);
}

bool FixNoseHooverNpt::tilts_barostatted() const {
  return std::any_of(settings_.tilt_dims.begin(), settings_.tilt_dims.end(),
                     [](bool on) { return on; });
}

void FixNoseHooverNpt::barostat_chain_step(const Simulation& sim) {
  double twice_ke = 0;
  int dims = 0;
  for (int d = 0; d < 3; ++d)
    if (settings_.dims[d]) {
      twice_ke += mass_ * omega_dot_[d] * omega_dot_[d];
      ++dims;
    }
  for (int t = 0; t < 3; ++t)
    if (settings_.tilt_dims[t]) {
      twice_ke += mass_ * tilt_omega_dot_[t] * tilt_omega_dot_[t];
      ++dims;
    }
  // LAMMPS nhc_press_integrate: Q₁ = k_B T/ω_P²; an iso barostat is one degree of freedom (with
  // barostatted tilts LAMMPS's pstyle is TRICLINIC: every component counts).
  const double dof = settings_.iso && !tilts_barostatted() ? 1.0 : dims;
  const double factor = barostat_chain_.half_step(twice_ke, dof, 1.0, sim.dt);
  for (int d = 0; d < 3; ++d)
    if (settings_.dims[d]) omega_dot_[d] *= factor;
  for (int t = 0; t < 3; ++t)
    if (settings_.tilt_dims[t]) tilt_omega_dot_[t] *= factor;
}

void FixNoseHooverNpt::atom_chain_step(Simulation& sim) {
  std::size_t n = 0;
  const double twice_ke = group_twice_kinetic(sim.atoms, group_bit_, n);
  const double dof = std::max(3.0 * static_cast<double>(n) - 3.0, 1.0);
  scale_group_velocities(sim.atoms, group_bit_, atom_chain_.half_step(twice_ke, dof, dof, sim.dt));
}

void FixNoseHooverNpt::barostat_kick(Simulation& sim) {
  const ThermoState thermo = sim.thermo();
  int dims = 0;
  for (int d = 0; d < 3; ++d) dims += settings_.dims[d] ? 1 : 0;
  // 2K/(3N) of eq. (1), or for lammps_mtk Σ_d m v_d²/(d N) of eq. (4), and the divisor of μ.
  const double divisor = (settings_.lammps_mtk ? dims : 3.0) * static_cast<double>(sim.atoms.nlocal);
  double twice_ke = 0;
  if (settings_.lammps_mtk) {
    const Vec3 mvv = group_twice_kinetic_components(sim.atoms, group_bit_);
    for (int d = 0; d < 3; ++d) twice_ke += settings_.dims[d] ? mvv[d] : 0.0;
  } else {
    std::size_t n_group = 0;
    twice_ke = group_twice_kinetic(sim.atoms, group_bit_, n_group);
  }
  const double mtk = twice_ke / divisor;
  // iso: the scalar pressure, or for two coupled dimensions the mean of their components
  // (LAMMPS FixNH::couple).
  const Mat3 fdev = deviatoric_ ? deviatoric_force(sim.box) : Mat3::Zero();  // eq. (7)
  double coupled = 0;
  for (int d = 0; d < 3; ++d)
    if (settings_.dims[d]) coupled += thermo.pressure_tensor[d];
  coupled = dims == 3 ? thermo.pressure : coupled / dims;
  double trace = 0;
  for (int d = 0; d < 3; ++d) {
    if (!settings_.dims[d]) continue;
    const double p = settings_.iso ? coupled : thermo.pressure_tensor[d];
    double force = (p - settings_.pressure) * thermo.volume / nktv2p + mtk;  // eV
    if (deviatoric_) force -= fdev(d, d) / nktv2p;
    omega_dot_[d] += 0.5 * sim.dt * force / mass_;
    trace += omega_dot_[d];
  }
  mu_ = trace / divisor;
  // Eq. (5): the shear pressures P_xy, P_xz, P_yz (Voigt 3, 4, 5), less F_t of eq. (7).
  static constexpr std::array<std::array<int, 2>, 3> tilt_entry{{{0, 1}, {0, 2}, {1, 2}}};
  for (int t = 0; t < 3; ++t) {
    if (!settings_.tilt_dims[t]) continue;
    double force = thermo.pressure_tensor[3 + t] * thermo.volume / nktv2p;  // eV
    if (deviatoric_) force -= fdev(tilt_entry[t][0], tilt_entry[t][1]) / nktv2p;
    tilt_omega_dot_[t] += 0.5 * sim.dt * force / mass_;
  }
}

void FixNoseHooverNpt::barostat_velocity_scaling(Simulation& sim) const {
  // With barostatted tilts: eq. (6) between two quarter steps of the diagonal (LAMMPS nh_v_press).
  if (tilts_barostatted()) {
    Vec3 quarter;
    for (int d = 0; d < 3; ++d) quarter[d] = std::exp(-0.25 * sim.dt * (omega_dot_[d] + mu_));
    const double half_dt = 0.5 * sim.dt;
    const Vec3& w = tilt_omega_dot_;
    Atoms& a = sim.atoms;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < a.nlocal; ++i) {
      if (!(a.mask[i] & group_bit_)) continue;
      Vec3 v = a.v[i].cwiseProduct(quarter);
      v.x() -= half_dt * (v.y() * w[0] + v.z() * w[1]);
      v.y() -= half_dt * v.z() * w[2];
      a.v[i] = v.cwiseProduct(quarter);
    }
    return;
  }
  Vec3 factor;
  for (int d = 0; d < 3; ++d) factor[d] = std::exp(-0.5 * sim.dt * (omega_dot_[d] + mu_));
  Atoms& a = sim.atoms;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit_) a.v[i] = a.v[i].cwiseProduct(factor);
}

void FixNoseHooverNpt::velocity_kick(Simulation& sim) const {
  Atoms& a = sim.atoms;
  const double dtf = 0.5 * sim.dt * units::metal::ftm2v;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit_) a.v[i] += (dtf / a.mass_of(i)) * a.f[i];
}

void FixNoseHooverNpt::dilate(Simulation& sim) {
  if (tilts_barostatted() || sim.box.triclinic()) {
    dilate_triclinic(sim);
    return;
  }
  geometry::Box& box = sim.box;
  Atoms& a = sim.atoms;
  for (int d = 0; d < 3; ++d) {
    if (!settings_.dims[d]) continue;
    // h ← h e^{½Δt ω̇_d} about the box centre c (LAMMPS FixNH::remap, default fixedpoint).
    const double c = 0.5 * (box.lo[d] + box.hi[d]), e = std::exp(0.5 * sim.dt * omega_dot_[d]);
    box.lo[d] = c + (box.lo[d] - c) * e;
    box.hi[d] = c + (box.hi[d] - c) * e;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < a.nlocal; ++i) a.x[i][d] = c + (a.x[i][d] - c) * e;
  }
  volume_ = box.volume();
  update_strain_energy(box);
}

// ḣ = ω̇ h over ½Δt with ω̇ and h upper triangular, in LAMMPS FixNH::remap's time-symmetric order:
// the tilts by a quarter (xz: an eighth around the others) of the step, the diagonal, the tilts
// again. The tilt updates read the edge lengths of the cell before this half step (LAMMPS's
// domain->h until set_global_box).
void FixNoseHooverNpt::dilate_triclinic(Simulation& sim) {
  geometry::Box& box = sim.box;
  const geometry::Box old = box;
  const double dto = 0.5 * sim.dt;
  const Vec3 l = old.length(), &w = omega_dot_, &wt = tilt_omega_dot_;  // wt: xy, xz, yz
  const auto& tilt_on = settings_.tilt_dims;
  double &xy = box.tilt[0], &xz = box.tilt[1], &yz = box.tilt[2];
  auto shear = [](double& t, double e, double increment) { t = (t * e + increment) * e; };
  auto tilt_half = [&] {
    if (tilt_on[1]) shear(xz, std::exp(dto / 8 * w.x()), dto / 4 * (wt[0] * yz + wt[1] * l.z()));
    if (tilt_on[2]) shear(yz, std::exp(dto / 4 * w.y()), dto / 2 * wt[2] * l.z());
    if (tilt_on[0]) shear(xy, std::exp(dto / 4 * w.x()), dto / 2 * wt[0] * l.y());
    if (tilt_on[1]) shear(xz, std::exp(dto / 8 * w.x()), dto / 4 * (wt[0] * yz + wt[1] * l.z()));
  };
  tilt_half();
  for (int d = 0; d < 3; ++d) {
    if (!settings_.dims[d]) continue;
    const double c = 0.5 * (box.lo[d] + box.hi[d]), e = std::exp(dto * w[d]);
    box.lo[d] = c + (box.lo[d] - c) * e;
    box.hi[d] = c + (box.hi[d] - c) * e;
    // A tilt left alone follows its second edge (LAMMPS scalexy, scalexz, scaleyz).
    if (d == 1 && !tilt_on[0]) xy *= e;
    if (d == 2 && !tilt_on[1]) xz *= e;
    if (d == 2 && !tilt_on[2]) yz *= e;
  }
  tilt_half();
  if (!settings_.flip) {
    try {
      box.check_tilt(fmt::format("step {}: npt with flip = false (LAMMPS flip no)", sim.step));
    } catch (const InputError& e) {
      throw RunError(e.what());
    }
  }
  Atoms& a = sim.atoms;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    a.x[i] = box.from_fractional(old.to_fractional(a.x[i]));
  volume_ = box.volume();
  update_strain_energy(box);
}

double FixNoseHooverNpt::energy_added() const {
  double e = atom_chain_.energy() + barostat_chain_.energy() +
             settings_.pressure * (volume_ - volume0_) / nktv2p;
  for (int d = 0; d < 3; ++d)
    if (settings_.dims[d]) e += 0.5 * mass_ * omega_dot_[d] * omega_dot_[d];
  for (int t = 0; t < 3; ++t)
    if (settings_.tilt_dims[t]) e += 0.5 * mass_ * tilt_omega_dot_[t] * tilt_omega_dot_[t];
  e += strain_energy_;
  return -e;  // eq. (3): the extended variables hold this energy
}

FixState FixNoseHooverNpt::state() const {
  FixState s{{"omega_dot", "1/ps", {omega_dot_.x(), omega_dot_.y(), omega_dot_.z()}},
             {"barostat_mass", "eV ps^2", {mass_}},
             {"mu", "1/ps", {mu_}},
             {"volume0", "Angstrom^3", {volume0_}},
             {"volume", "Angstrom^3", {volume_}}};
  if (tilts_barostatted())
    s.push_back({"omega_dot_tilt",
                 "1/ps",
                 {tilt_omega_dot_.x(), tilt_omega_dot_.y(), tilt_omega_dot_.z()}});
  if (deviatoric_) {
    s.push_back({"strain_reference",
                 "bar Angstrom",
                 {sigma_(0, 0), sigma_(1, 1), sigma_(2, 2), sigma_(0, 1), sigma_(0, 2), sigma_(1, 2)}});
    s.push_back({"strain_energy", "eV", {strain_energy_}});
  }
  atom_chain_.save(s, "thermostat");
  barostat_chain_.save(s, "barostat_chain");
  return s;
}

void FixNoseHooverNpt::restore(const FixState& s) {
  omega_dot_ = Vec3(fix_state_values(s, name(), "omega_dot", 3).data());
  mass_ = fix_state_value(s, name(), "barostat_mass");
  mu_ = fix_state_value(s, name(), "mu");
  if (tilts_barostatted())
    tilt_omega_dot_ = Vec3(fix_state_values(s, name(), "omega_dot_tilt", 3).data());
  volume0_ = fix_state_value(s, name(), "volume0");
  volume_ = fix_state_value(s, name(), "volume");
  deviatoric_ = settings_.tilt_pressure != Vec3::Zero();
  if (deviatoric_) {
    const auto v = fix_state_values(s, name(), "strain_reference", 6);
    sigma_ << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
    strain_energy_ = fix_state_value(s, name(), "strain_energy");
  }
  atom_chain_.restore(s, name(), "thermostat");
  barostat_chain_.restore(s, name(), "barostat_chain");
}

}  // namespace shockfield::md
