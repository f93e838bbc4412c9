#pragma once
// A Fix hooks into the named stages of the MD time step (LAMMPS fix semantics). The step is
//   initial_integrate → post_integrate → [neighbour rebuild or ghost update] → force
//   → post_force → final_integrate → end_of_step
// Integrators, thermostats, walls, loading and diagnostics are all fixes.
#include <string>
#include <vector>

namespace shockfield::md {

class Simulation;

class Fix {
 public:
  virtual ~Fix() = default;
  virtual std::string name() const = 0;
  /// Called once before the first step of a stage (forces are current).
  virtual void setup(Simulation&) {}
  virtual void initial_integrate(Simulation&) {}
  virtual void post_integrate(Simulation&) {}
  virtual void post_force(Simulation&) {}
  virtual void final_integrate(Simulation&) {}
  virtual void end_of_step(Simulation&) {}
  /// Energy this fix has added to the system so far (eV), for the conserved-quantity column.
  virtual double energy_added() const { return 0.0; }
  /// State that must survive a checkpoint (thermostat variables, ...), and its restoration.
  virtual std::vector<double> state() const { return {}; }
  virtual void restore(const std::vector<double>&) {}
};

}  // namespace shockfield::md
