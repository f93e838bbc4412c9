#include "shockfield/dbm/stability_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace shockfield::dbm {
namespace {

/// `held`: a state the run holds over a growing region (initial, fed in, Riemann star, CJ), not a
/// peak the gas passes through (the von Neumann state of a ZND front); only a held one is judged
/// by its smooth modes (kSmoothGrowthFactor below).
struct NamedState {
  std::string name;
  Macro macro;
  bool held = true;
};

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
    states.push_back({"von Neumann state of [reaction]", macro_of_gas(c.reaction->theory.von_neumann), false});
  }
  return states;
}

/// A smooth mode (NND second-order upwind, linear_stability.hpp kSmoothTheta) counts as unstable
/// when it grows by more than this factor over the run: below it a perturbation stays at the size of
/// what seeds it (truncation error, start-up waves); above it (the von Neumann state of the
/// detonation example held by an inflow at dx = 0.0025: exp(31)) the run breaks down
/// (docs/theory/dbm.md, "Smooth modes").
constexpr double kSmoothGrowthFactor = 10.0;

bool smooth_modes_grow(const NamedState& s, const StabilityReport& r, double end_time) {
  return s.held && r.smooth_rate * end_time > std::log(kSmoothGrowthFactor);
}

/// The rate a state is ranked by: the run's (first-order upwind) or, when held, its smooth modes'.
double severity(const NamedState& s, const StabilityReport& r) {
  return s.held ? std::max(r.discrete_rate, r.smooth_rate) : r.discrete_rate;
}

std::string describe(const NamedState& s) {
  return fmt::format("the {} (rho = {:.4g}, v = ({:.4g}, {:.4g}), T = {:.4g})", s.name, s.macro.rho, s.macro.ux, s.macro.uy,
                     s.macro.T);
}

std::string smooth_diagnosis(const NamedState& state, const StabilityReport& r, const StabilityProblem& p,
                             double end_time) {
  std::string text = fmt::format(
      "{} is linearly unstable to smooth waves with {} at tau = {:.4g}, dx = {:.4g}: with the second-order upwind "
      "stencil NND uses where its limiter is inactive, the mode k dx = ({:.3g}, {:.3g}) grows as exp({:.3g} t), a factor "
      "{:.2g} by end_time = {:.4g} (more than {:g} is refused; von Neumann analysis, docs/theory/dbm.md). ",
      describe(state), p.model.name, p.tau, p.dx, r.smooth_theta_x, r.smooth_theta_y, r.smooth_rate,
      std::exp(std::min(r.smooth_rate * end_time, 700.0)), end_time, kSmoothGrowthFactor);
  if (r.model_rate > tolerance_rate(p.tau))
    text += fmt::format("The BGK model itself is unstable at this state (growth {:.3g}) and only the grid damps it, the "
                        "more the larger dx/tau (here {:.3g}): use a coarser grid or a smaller model.tau (refining dx "
                        "makes it worse), or ",
                        r.model_rate, p.dx / p.tau);
  else
    text += "Use ";
  return text + "model.speeds and model.eta0 made for this temperature, or a shorter run.end_time; "
                "model.stability_check = \"warn\" runs anyway";
}

std::string diagnosis(const NamedState& state, const StabilityReport& r, const StabilityProblem& p, double end_time) {
  const double tolerance = tolerance_rate(p.tau);
  if (r.discrete_rate <= tolerance) return smooth_diagnosis(state, r, p, end_time);
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
  double worst = -INFINITY;
  result.stable_dt = INFINITY;
  result.verdict = "stable";
  for (const NamedState& state : case_states(c)) {
    const StabilityReport r = analyse_stability(p, state.macro);
    result.stable_dt = std::min(result.stable_dt, r.stable_dt);
    if (severity(state, r) > worst) result.worst = r, result.worst_state = state.name, worst = severity(state, r);
    if (r.discrete_rate <= tolerance_rate(p.tau) && !smooth_modes_grow(state, r, c.end_time)) continue;
    result.verdict = "unstable";
    const std::string message = diagnosis(state, r, p, c.end_time);
    if (result.mode == "error") model.fail("stability_check", message);
    std::fprintf(stderr, "warning: %s\n", message.c_str());
  }
  return result;
}

void derive_stability(const Config& root, const CaseStability& s) {
  root.derive("linear_stability", s.verdict);
  if (s.verdict == "not checked") return;
  root.derive("linear_stability_worst_state", s.worst_state);
  root.derive("linear_stability_growth_rate", s.worst.discrete_rate);
  root.derive("linear_stability_growth_rate_small_dt", s.worst.semi_discrete_rate);
  root.derive("linear_stability_model_growth_rate", s.worst.model_rate);
  root.derive("linear_stability_smooth_growth_rate", s.worst.smooth_rate);
  root.derive("linear_stability_stable_time_step", s.stable_dt);
}

}  // namespace shockfield::dbm
