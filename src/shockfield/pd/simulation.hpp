#pragma once
// A peridynamic run: the body (points, families), its density, a force model and the
// velocity-Verlet loop of Liu et al. (2025) eq. 1, ρ·ü = L + b, with hooks at named stages (as md/ and
// mpm/ do). Motion is restricted to the body's dimension (a 1D bar moves along x only: the
// lateral "pulley" constraint of the paper's Fig. 2).
//
// Velocity-Verlet (LAMMPS fix nve): v ← v + ½Δt·a;  y ← y + Δt·v;  a ← L(y, v)/ρ;  v ← v + ½Δt·a.
// The force model sees the half-step velocity.
#include <functional>
#include <memory>
#include <vector>

#include "shockfield/pd/family.hpp"
#include "shockfield/pd/force_model.hpp"
#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

class Simulation {
 public:
  /// before_force: after the drift, before the forces of the new positions (a prescribed
  /// displacement sets its points); after_force: before the second half kick (a held point drops
  /// its force). In both, time() is already the time the step ends at.
  enum class Stage { before_force, after_force, end_of_step };
  using Hook = std::function<void(Simulation&)>;

  /// `density` is ρ per point (one value for all when its size is 1). The cloud and family must
  /// outlive the simulation (the force model holds references to them).
  Simulation(const PointCloud& cloud, const Family& family, std::unique_ptr<ForceModel> model,
             std::vector<double> density);

  /// Computes the forces of the initial state (LAMMPS "setup", with the before_force and after_force
  /// hooks at t = 0); called by the first step if not yet.
  void setup();
  /// One velocity-Verlet step. RunError when a position or velocity stops being finite.
  void step(double dt);
  /// Puts back a checkpointed state (positions, velocities, the force density of the last
  /// evaluation, the clock): the next step continues bitwise as if never stopped.
  void restore(std::vector<Vec3> y, std::vector<Vec3> v, std::vector<Vec3> force_density, long long steps,
               double time);
  /// The RunError step() throws when the state of the step of size dt stopped being finite (a
  /// decomposed run raises it from the gathered whole body: run_ranks.hpp).
  [[noreturn]] void throw_unstable(double dt) const;
  void add_hook(Stage stage, Hook hook) { hooks_.push_back({stage, std::move(hook)}); }
  /// Largest stable step for this body and model (the model's estimate) [s].
  double stable_step() const { return model_->stable_step(density_); }

  const PointCloud& cloud() const { return cloud_; }
  const Family& family() const { return family_; }
  ForceModel& model() { return *model_; }
  const std::vector<double>& density() const { return density_; }
  std::vector<Vec3>& positions() { return y_; }
  std::vector<Vec3>& velocities() { return v_; }
  const std::vector<Vec3>& positions() const { return y_; }
  const std::vector<Vec3>& velocities() const { return v_; }
  /// The force density of the last evaluation; an after_force hook may change it (a held point:
  /// regions.hpp) before the velocities are kicked with it.
  std::vector<Vec3>& force_density() { return f_; }
  const std::vector<Vec3>& force_density() const { return f_; }
  long long step_count() const { return steps_; }
  double time() const { return time_; }
  /// Kinetic energy Σ ½ρV|v|² [J per unit of the missing dimensions].
  double kinetic_energy() const;
  /// Total momentum Σ ρV v.
  Vec3 momentum() const;

 private:
  void run_hooks(Stage stage);
  void clamp_dimensions(std::vector<Vec3>& a) const;

  const PointCloud& cloud_;
  const Family& family_;
  std::unique_ptr<ForceModel> model_;
  std::vector<double> density_;
  std::vector<Vec3> y_, v_, f_;
  std::vector<std::pair<Stage, Hook>> hooks_;
  bool ready_ = false;
  long long steps_ = 0;
  double time_ = 0.0;
};

}  // namespace shockfield::pd
