#include "shockfield/md/fixes/nose_hoover.hpp"

#include <cmath>

#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/velocity.hpp"

namespace shockfield::md {

using units::metal::boltz;

FixNoseHoover::FixNoseHoover(double temperature, double damping, int chain, std::uint32_t group_bit)
    : FixNve(group_bit), target_(temperature), period_(damping),
      eta_(chain, 0.0), eta_dot_(chain + 1, 0.0), eta_dotdot_(chain, 0.0), mass_(chain, 0.0) {}

void FixNoseHoover::initial_integrate(Simulation& sim) {
  integrate_chain(sim);
  FixNve::initial_integrate(sim);
}

void FixNoseHoover::final_integrate(Simulation& sim) {
  FixNve::final_integrate(sim);
  integrate_chain(sim);
}

void FixNoseHoover::integrate_chain(Simulation& sim) {
  Atoms& a = sim.atoms;
  std::size_t n = 0;
  double twice_ke = group_twice_kinetic(a, group_bit_, n);
  dof_ = std::max(3.0 * static_cast<double>(n) - 3.0, 1.0);
  const int m = static_cast<int>(eta_.size());
  const double kt = boltz * target_, omega2 = 1.0 / (period_ * period_);
  const double target_twice_ke = dof_ * kt;
  mass_[0] = dof_ * kt / omega2;
  for (int k = 1; k < m; ++k) mass_[k] = kt / omega2;
  const double dt = sim.dt, dt4 = 0.25 * dt, dt8 = 0.125 * dt;
  eta_dotdot_[0] = (twice_ke - target_twice_ke) / mass_[0];
  // Outer chain members, from the far end inwards (eta_dot_[m] stays 0).
  for (int k = m - 1; k > 0; --k) {
    const double e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
  double e = std::exp(-dt8 * eta_dot_[1]);
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  const double scale = std::exp(-0.5 * dt * eta_dot_[0]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & group_bit_) a.v[i] *= scale;
  twice_ke *= scale * scale;
  eta_dotdot_[0] = (twice_ke - target_twice_ke) / mass_[0];
  for (int k = 0; k < m; ++k) eta_[k] += 0.5 * dt * eta_dot_[k];
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  for (int k = 1; k < m; ++k) {
    e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dotdot_[k] = (mass_[k - 1] * eta_dot_[k - 1] * eta_dot_[k - 1] - kt) / mass_[k];
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
}

double FixNoseHoover::energy_added() const {
  // The chain energy is stored with the opposite sign: the thermostat *holds* it.
  const double kt = boltz * target_;
  double e = dof_ * kt * eta_[0] + 0.5 * mass_[0] * eta_dot_[0] * eta_dot_[0];
  for (std::size_t k = 1; k < eta_.size(); ++k) e += kt * eta_[k] + 0.5 * mass_[k] * eta_dot_[k] * eta_dot_[k];
  return -e;
}

std::vector<double> FixNoseHoover::state() const {
  std::vector<double> s = eta_;
  s.insert(s.end(), eta_dot_.begin(), eta_dot_.end());
  s.insert(s.end(), eta_dotdot_.begin(), eta_dotdot_.end());
  s.insert(s.end(), mass_.begin(), mass_.end());
  s.push_back(dof_);
  return s;
}

void FixNoseHoover::restore(const std::vector<double>& s) {
  std::size_t k = 0;
  for (auto& v : eta_) v = s.at(k++);
  for (auto& v : eta_dot_) v = s.at(k++);
  for (auto& v : eta_dotdot_) v = s.at(k++);
  for (auto& v : mass_) v = s.at(k++);
  dof_ = s.at(k);
}

}  // namespace shockfield::md
