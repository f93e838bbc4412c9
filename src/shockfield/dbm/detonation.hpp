#pragma once
// A planar detonation along +x with the reactive DBM (reaction.hpp): the ZND-like ignition start
// and the front tracking used by the case files, the tests and examples/dbm_detonation.
#include <vector>

#include "shockfield/dbm/detonation_theory.hpp"
#include "shockfield/dbm/reaction.hpp"

namespace shockfield::dbm {

struct IgnitionSpec {
  double x = 0.0;      ///< burnt CJ gas (λ = 0) for x < x; 0: no ignition region
  double width = 0.0;  ///< then unburnt gas (λ = 1) at the von Neumann state on [x, x + width)
};

/// The [reaction] table of a case file (reaction_case.hpp).
struct ReactionSpec {
  RateLaw law;
  IgnitionSpec ignition;
  double inflow_lambda = 1.0;  ///< λ of gas entering through inflow sides
  GasState fresh;              ///< the gas ahead of the detonation ([initial] right/uniform state)
  ChapmanJouguet theory;       ///< CJ speed and states for `fresh`, γ and Q
  /// p at which the front is tracked: halfway between the fresh and the CJ pressure.
  double front_pressure() const { return 0.5 * (fresh.p + theory.cj.p); }
};

/// f = f^eq and λ of the ZND-like start: CJ state (burnt) | von Neumann state (fresh) | `fresh`
/// (λ = 1), with the states of chapman_jouguet(fresh, γ, Q). `rest(x, y)` gives the state of the
/// cells beyond the ignition region (the case's [initial]).
void initialize_detonation(Simulation& sim, ReactiveFlow& flow, const IgnitionSpec& ignition,
                           const ChapmanJouguet& cj, const std::function<Macro(double, double)>& rest);

/// x where p = ρT along row j first exceeds `threshold` coming from +x (linear interpolation
/// between cell centres); the domain end when nothing does.
double pressure_front(const Simulation& sim, int row, double threshold);

/// Least-squares slope of x(t): the measured front speed.
double fitted_speed(const std::vector<double>& t, const std::vector<double>& x);

}  // namespace shockfield::dbm
