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

/// A planar detonation tube on nx × 1 cells (D2V16 speeds 1, 2, 3, 4, η0 = 2): closed
/// (reflecting) end at x = 0, outflow at x = length, ZND-like start at x = 0.5 — or, with
/// `piston`, an inert control: the whole [0, ignition_width) at the von Neumann state and
/// von Neumann gas flowing in at x = 0 (a steady shock at D_CJ, uniform behind).
struct DetonationTubeSetup {
  GasState fresh{1.0, 0.0, 0.6};
  double gamma = 1.4;
  RateLaw law;
  double length = 6.0, dx = 0.01, tau = 2e-3, t_end = 2.0;
  double ignition_width = 0.1;
  bool piston = false;
};

struct DetonationTubeResult {
  double speed = 0.0;  ///< fitted front speed over the second half of the run
  ChapmanJouguet theory;
  std::vector<double> x, rho, p, lambda, d2xx;  ///< final line profile (d2xx = Δ*_2xx)
};

DetonationTubeResult run_detonation_tube(const DetonationTubeSetup& setup);

}  // namespace shockfield::dbm
