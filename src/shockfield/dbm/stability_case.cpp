#include "shockfield/dbm/stability_case.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

namespace shockfield::dbm {
namespace {

using NamedState = std::pair<std::string, Macro>;

Macro macro_of_gas(const GasState& g) { return {g.rho, g.u, 0.0, g.p / g.rho}; }

/// The uniform states the run starts from, is fed with or is expected to reach.
std::vector<NamedState> case_states(const DbmCase& c) {
  std::vector<NamedState> states;
  if (c.initial.riemann) {
    states.push_back({"initial.left state", c.initial.left});
    states.push_back({"initial.right state", c.initial.right});
  } else {
    states.push_back({"initial.state", c.initial.left});
  }
  const std::array<const char*, 4> sides{"x_low", "x_high", "y_low", "y_high"};
  for (std::size_t s = 0; s < 4; ++s)
    if (feeds_gas(c.boundaries.side[s].kind))
      states.push_back({fmt::format("boundary.{}_state", sides[s]), c.boundaries.side[s].state});
  if (c.exact_star) {
    const RiemannStar& r = *c.exact_star;
    states.push_back({"star state left of the contact (exact Riemann solution)", {r.rho_left, r.u, 0.0, r.p / r.rho_left}});
    states.push_back({"star state right of the contact (exact Riemann solution)", {r.rho_right, r.u, 0.0, r.p / r.rho_right}});
  }
  if (c.reaction) {
    states.push_back({"Chapman-Jouguet state of [reaction]", macro_of_gas(c.reaction->theory.cj)});
    states.push_back({"von Neumann state of [reaction]", macro_of_gas(c.reaction->theory.von_neumann)});
  }
  return states;
}

std::string describe(const NamedState& s) {
  return fmt::format("the {} (rho = {:.4g}, u = ({:.4g}, {:.4g}), T = {:.4g})", s.first, s.second.rho, s.second.ux,
                     s.second.uy, s.second.T);
}

std::string diagnosis(const NamedState& state, const StabilityReport& r, const StabilityProblem& p, double end_time) {
  const double tolerance = tolerance_rate(p.tau);
  std::string text = fmt::format(
      "{} is linearly unstable with {} at tau = {:.4g}, dx = {:.4g}: perturbations grow as exp({:.3g} t) (a factor "
      "{:.2g} by end_time = {:.4g}; von Neumann analysis, docs/theory/dbm.md)",
      describe(state), p.model.name, p.tau, p.dx, r.discrete_rate, std::exp(std::min(r.discrete_rate * end_time, 700.0)),
      end_time);
  if (r.semi_discrete_rate > tolerance) {
    text += fmt::format(" for every time step (growth {:.3g} as dt -> 0, mode k dx = ({:.3g}, {:.3g}))",
                        r.semi_discrete_rate, r.theta_x, r.theta_y);
    if (r.model_rate > tolerance)
      text += fmt::format("; the BGK model itself is unstable at this state (growth {:.3g} at |k| tau = {:.3g}: short "
                          "waves, where f^eq = C^-1 M^eq has negative weights), so refining dx makes it worse",
                          r.model_rate, r.model_k_tau);
    text += ". Use model.speeds and model.eta0 made for this temperature (e.g. speeds = [3, 2, 5, 10], eta0 = 8; "
            "stable temperature windows in docs/theory/dbm.md) or keep the temperatures lower";
  } else {
    text += fmt::format(" with dt = {:.4g} (amplification {:.6g} per step); the largest stable time step here is "
                        "{:.4g}: set run.dt <= {:.4g} or lower run.courant",
                        p.dt, r.amplification, r.stable_dt, r.stable_dt);
  }
  return text + "; model.stability_check = \"warn\" runs anyway";
}

}  // namespace

CaseStability check_case_stability(const Config& model, const DbmCase& c) {
  CaseStability result;
  result.mode = model.get_choice_or("stability_check", {"error", "warn", "off"}, "error");
  if (result.mode == "off") return result;
  StabilityProblem p;
  p.model = c.model;
  p.b = 2.0 / (c.bgk.gamma - 1.0);
  p.tau = c.bgk.tau, p.dt = c.bgk.dt, p.dx = c.lattice.dx, p.dy = c.lattice.dy;
  p.two_dimensional = c.lattice.ny > 1;
  p.stencil = c.bgk.spectral_convection ? Stencil::exact : Stencil::first_order_upwind;
  p.resolution = p.two_dimensional ? 16 : 32;
  result.worst.discrete_rate = -INFINITY;
  result.stable_dt = INFINITY;
  for (const NamedState& state : case_states(c)) {
    const StabilityReport r = analyse_stability(p, state.second);
    result.stable_dt = std::min(result.stable_dt, r.stable_dt);
    if (r.discrete_rate > result.worst.discrete_rate) result.worst = r, result.worst_state = state.first;
    if (r.discrete_rate <= tolerance_rate(p.tau)) continue;
    const std::string message = diagnosis(state, r, p, c.end_time);
    if (result.mode == "error") model.fail("stability_check", message);
    std::fprintf(stderr, "warning: %s\n", message.c_str());
  }
  result.verdict = result.worst.discrete_rate > tolerance_rate(p.tau) ? "unstable" : "stable";
  return result;
}

void derive_stability(const Config& root, const CaseStability& s) {
  root.derive("linear_stability", s.verdict);
  if (s.verdict == "not checked") return;
  root.derive("linear_stability_worst_state", s.worst_state);
  root.derive("linear_stability_growth_rate", s.worst.discrete_rate);
  root.derive("linear_stability_growth_rate_small_dt", s.worst.semi_discrete_rate);
  root.derive("linear_stability_model_growth_rate", s.worst.model_rate);
  root.derive("linear_stability_stable_time_step", s.stable_dt);
}

}  // namespace shockfield::dbm
