#pragma once
// A Fix hooks into the named stages of the MD time step (LAMMPS fix semantics). The step is
//   initial_integrate → post_integrate → [neighbour rebuild or ghost update] → force
//   → post_force → final_integrate → end_of_step
// Integrators, thermostats, walls, loading and diagnostics are all fixes.
#include <string>
#include <vector>

namespace shockfield::md {

class Simulation;

/// One named variable of a fix's state, its unit in LAMMPS metal units (eV, ps, Angstrom, bar, K,
/// g/mol; "1" for a pure number) and its values: one dataset of the checkpoint (fix<k>_<fix>.<name>).
struct FixStateItem {
  std::string name;
  std::string units;
  std::vector<double> values;
};
using FixState = std::vector<FixStateItem>;

/// The values of `name` in a restored state, exactly `count` of them; InputError naming the fix
/// and the variable otherwise (a checkpoint of another fix or layout).
const std::vector<double>& fix_state_values(const FixState& state, const std::string& fix, const std::string& name,
                                            std::size_t count);
inline double fix_state_value(const FixState& state, const std::string& fix, const std::string& name) {
  return fix_state_values(state, fix, name, 1)[0];
}

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
  /// State that must survive a checkpoint (thermostat variables, ...), named, and its restoration.
  virtual FixState state() const { return {}; }
  virtual void restore(const FixState&) {}
};

}  // namespace shockfield::md
