#include "shockfield/md/fixes/nose_hoover.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/velocity.hpp"

namespace shockfield::md {

using units::metal::boltz;

NoseHooverChain::NoseHooverChain(int length, double temperature, double period)
    : kt_(boltz * temperature), mass_kt_(kt_), period_(period),
      eta_(length, 0.0), eta_dot_(length + 1, 0.0), eta_dotdot_(length, 0.0), mass_(length, 0.0) {
  // The outer members' forces at rest, (Q_{k−1}·0 − k_B T)/Q_k = −ω², which the first half step
  // uses before it computes its own (LAMMPS FixNH::setup).
  for (int k = 1; k < length; ++k) eta_dotdot_[k] = -1.0 / (period * period);
}

double NoseHooverChain::half_step(double twice_ke, double dof, double first_mass_dof, double dt) {
  dof_ = dof;
  const int m = static_cast<int>(eta_.size());
  if (m == 0) return 1.0;
  const double omega2 = 1.0 / (period_ * period_);
  const double target_twice_ke = dof * kt_;
  mass_[0] = first_mass_dof * mass_kt_ / omega2;
  for (int k = 1; k < m; ++k) mass_[k] = mass_kt_ / omega2;
  const double dt4 = 0.25 * dt, dt8 = 0.125 * dt;
  eta_dotdot_[0] = (twice_ke - target_twice_ke) / mass_[0];
  // Outer chain members, from the far end inwards (eta_dot_[m] stays 0).
  for (int k = m - 1; k > 0; --k) {
    const double e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
  double e = std::exp(-dt8 * eta_dot_[1]);
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  const double scale = std::exp(-0.5 * dt * eta_dot_[0]);
  twice_ke *= scale * scale;
  eta_dotdot_[0] = (twice_ke - target_twice_ke) / mass_[0];
  for (int k = 0; k < m; ++k) eta_[k] += 0.5 * dt * eta_dot_[k];
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  for (int k = 1; k < m; ++k) {
    e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dotdot_[k] = (mass_[k - 1] * eta_dot_[k - 1] * eta_dot_[k - 1] - kt_) / mass_[k];
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
  return scale;
}

double NoseHooverChain::energy() const {
  if (eta_.empty()) return 0.0;
  double e = dof_ * kt_ * eta_[0] + 0.5 * mass_[0] * eta_dot_[0] * eta_dot_[0];
  for (std::size_t k = 1; k < eta_.size(); ++k) e += kt_ * eta_[k] + 0.5 * mass_[k] * eta_dot_[k] * eta_dot_[k];
  return e;
}

void NoseHooverChain::save(FixState& s, const std::string& prefix) const {
  s.push_back({prefix + "_eta", "1", eta_});
  s.push_back({prefix + "_eta_dot", "1/ps", eta_dot_});
  s.push_back({prefix + "_eta_dotdot", "1/ps^2", eta_dotdot_});
  s.push_back({prefix + "_mass", "eV ps^2", mass_});
  s.push_back({prefix + "_dof", "1", {dof_}});
}

void NoseHooverChain::restore(const FixState& s, const std::string& fix, const std::string& prefix) {
  eta_ = fix_state_values(s, fix, prefix + "_eta", eta_.size());
  eta_dot_ = fix_state_values(s, fix, prefix + "_eta_dot", eta_dot_.size());
  eta_dotdot_ = fix_state_values(s, fix, prefix + "_eta_dotdot", eta_dotdot_.size());
  mass_ = fix_state_values(s, fix, prefix + "_mass", mass_.size());
  dof_ = fix_state_value(s, fix, prefix + "_dof");
}

void check_extended_energy(const Simulation& sim, const char* fix, double energy, double dof, double temperature) {
  const double scale = dof * boltz * temperature;
  if (std::isfinite(energy) && std::abs(energy) <= runaway_factor * scale) return;
  throw RunError(fmt::format("step {}: the {} thermostat ran away: its variables hold {:.3g} eV, more than {:.0e} "
                             "N_f k_B T = {:.3g} eV (the conserved energy blows up while the atoms stay finite); "
                             "the time step ({} ps) is probably too large for the damping time of this fix",
                             sim.step, fix, energy, runaway_factor, runaway_factor * scale, sim.dt));
}

void scale_group_velocities(Atoms& atoms, std::uint32_t group_bit, double factor) {
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    if (atoms.mask[i] & group_bit) atoms.v[i] *= factor;
}

FixNoseHoover::FixNoseHoover(double temperature, double damping, int chain, std::uint32_t group_bit)
    : FixNve(group_bit), chain_(chain, temperature, damping) {}

void FixNoseHoover::initial_integrate(Simulation& sim) {
  integrate_chain(sim);
  FixNve::initial_integrate(sim);
}

void FixNoseHoover::final_integrate(Simulation& sim) {
  FixNve::final_integrate(sim);
  integrate_chain(sim);
  check_extended_energy(sim, "nvt", chain_.energy(), chain_.degrees_of_freedom(), chain_.temperature());
}

void FixNoseHoover::integrate_chain(Simulation& sim) {
  std::size_t n = 0;
  const double twice_ke = group_twice_kinetic(sim.atoms, group_bit_, n);
  const double dof = std::max(3.0 * static_cast<double>(n) - 3.0, 1.0);
  scale_group_velocities(sim.atoms, group_bit_, chain_.half_step(twice_ke, dof, dof, sim.dt));
}

FixState FixNoseHoover::state() const {
  FixState s;
  chain_.save(s, "thermostat");
  return s;
}

}  // namespace shockfield::md
