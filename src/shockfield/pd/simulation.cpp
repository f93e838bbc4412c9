#include "shockfield/pd/simulation.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {

Simulation::Simulation(const PointCloud& cloud, const Family& family, std::unique_ptr<ForceModel> model,
                       std::vector<double> density)
    : cloud_(cloud), family_(family), model_(std::move(model)), density_(std::move(density)) {
  if (density_.size() == 1) density_.assign(cloud.size(), density_.front());
  if (density_.size() != cloud.size())
    throw InputError(fmt::format("pd: {} densities for {} points", density_.size(), cloud.size()));
  for (double rho : density_)
    if (!(rho > 0.0)) throw InputError(fmt::format("pd: density {} (expected > 0 kg/m³)", rho));
  y_ = cloud.x;
  v_.assign(cloud.size(), Vec3::Zero());
  f_.assign(cloud.size(), Vec3::Zero());
}

void Simulation::clamp_dimensions(std::vector<Vec3>& a) const {
  if (cloud_.dim == 3) return;
  for (Vec3& x : a)
    for (int d = cloud_.dim; d < 3; ++d) x[d] = 0.0;
}

void Simulation::setup() {
  run_hooks(Stage::before_force);
  model_->compute(Kinematics{y_, v_, 0.0}, f_);
  clamp_dimensions(f_);
  ready_ = true;
  run_hooks(Stage::after_force);
}

void Simulation::step(double dt) {
  if (!ready_) setup();
  const auto n = static_cast<std::ptrdiff_t>(cloud_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    v_[i] += (0.5 * dt / density_[i]) * f_[i];
    y_[i] += dt * v_[i];
  }
  time_ += dt;
  run_hooks(Stage::before_force);
  model_->compute(Kinematics{y_, v_, dt}, f_);
  clamp_dimensions(f_);
  run_hooks(Stage::after_force);
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    v_[i] += (0.5 * dt / density_[i]) * f_[i];
    finite = finite && v_[i].allFinite() && y_[i].allFinite();
  }
  ++steps_;
  if (!finite) throw_unstable(dt);
  run_hooks(Stage::end_of_step);
}

void Simulation::throw_unstable(double dt) const {
  throw RunError(fmt::format("pd: non-finite positions or velocities at step {} (t = {:.6g} s): the time step "
                             "{:.6g} s is unstable (estimate {:.6g} s)",
                             steps_, time_, dt, stable_step()));
}

void Simulation::restore(std::vector<Vec3> y, std::vector<Vec3> v, std::vector<Vec3> force_density, long long steps,
                         double time) {
  if (y.size() != cloud_.size() || v.size() != cloud_.size() || force_density.size() != cloud_.size())
    throw InputError(fmt::format("pd: restored state has {} points, the body {}", y.size(), cloud_.size()));
  y_ = std::move(y), v_ = std::move(v), f_ = std::move(force_density);
  steps_ = steps, time_ = time;
  ready_ = true;
}

void Simulation::run_hooks(Stage stage) {
  for (auto& [s, hook] : hooks_)
    if (s == stage) hook(*this);
}

double Simulation::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < cloud_.size(); ++i) e += 0.5 * density_[i] * cloud_.volume[i] * v_[i].squaredNorm();
  return e;
}

Vec3 Simulation::momentum() const {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < cloud_.size(); ++i) p += density_[i] * cloud_.volume[i] * v_[i];
  return p;
}

}  // namespace shockfield::pd
