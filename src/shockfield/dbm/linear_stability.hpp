#pragma once
// Von Neumann (linear) stability of the compressible BGK DBM about a uniform state (ρ, u, T)
// (docs/theory/dbm.md, "Linear stability about a uniform state"). A perturbation
// δf(x) = δf̂ e^{i k·x} of the semi-discrete scheme evolves by dδf̂/dt = (−i S(k) + J) δf̂, with
//   J = −(I − ∂f^eq/∂f)/τ,  ∂f^eq/∂f = C⁻¹ · ∂M^eq/∂(ρ,u,T) · ∂(ρ,u,T)/∂(ρ,ρu,E) · W
// (W the rows of eqs. 20–22 that give ρ, ρu, E from f) the collision Jacobian and S(k) the
// diagonal convection symbol, v_k·k for the exact derivative or that of a linear branch of the
// NND scheme. One third-order Runge–Kutta step multiplies δf̂ by
//   G = I + A + A²/2 + A³/6,  A = Δt(−i S(k) + J),
// so ρ(G) > 1 means the run amplifies perturbations. The exact-symbol growth rate
// max Re λ(−i v·k + J) separates an instability of the model itself (BGK with the negative
// weights of f^eq = C⁻¹M^eq; no Δt cures it) from one of the time step.
#include <Eigen/Core>
#include <complex>
#include <string>

#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

using RealMatrix16 = Eigen::Matrix<double, kMoments, kMoments>;
using ComplexMatrix16 = Eigen::Matrix<std::complex<double>, kMoments, kMoments>;

/// ∂f^eq/∂f at the equilibrium of `state` (the derivative of M^eq by complex step, exact to
/// round-off). A projection: it leaves ρ, ρu, E unchanged.
RealMatrix16 equilibrium_jacobian(const VelocityModel& model, const MomentInversion& inversion,
                                  const Macro& state, double b);

/// The linear stencils the minmod-limited NND reconstruction switches between. With the slope
/// σ_i = minmod(Δ−, Δ+): σ = Δ− (upwind side smaller) gives the second-order upwind scheme,
/// σ = Δ+ the central difference, σ = 0 (at extrema) first-order upwind.
enum class Stencil { exact, second_order_upwind, central, first_order_upwind };
const char* stencil_name(Stencil s);

/// Symbol c of v ∂/∂x on a grid of spacing h for the mode e^{iθx/h}: (v ∂f/∂x)^ = c·f̂, c = i vθ/h
/// for the exact derivative; Re c ≥ 0 is the damping of the upwind stencils.
std::complex<double> convection_symbol(double v, double theta, double h, Stencil stencil);

/// The polynomial of one third-order (TVD, Shu–Osher) Runge–Kutta step for dy/dt = λy, z = λΔt.
inline std::complex<double> rk3_factor(std::complex<double> z) {
  return 1.0 + z + z * z / 2.0 + z * z * z / 6.0;
}

struct StabilityProblem {
  VelocityModel model;
  double b = 5.0, tau = 1e-3, dt = 1e-4, dx = 1e-2, dy = 1e-2;
  bool two_dimensional = true;  ///< false: a lattice one cell high, only k_y = 0 exists
  /// The stencil of the discrete analysis: first-order upwind, the one NND uses at every extremum
  /// and exactly on the odd–even mode, the mode that grows in NND runs (docs/theory/dbm.md).
  Stencil stencil = Stencil::first_order_upwind;
  int resolution = 32;  ///< wave numbers θ = kΔx per half axis, [0, π] (Nyquist) included
};

/// The smooth modes, |θ| ≤ π/4 on both axes (eight or more cells per wavelength): NND's minmod
/// slope is Δ− there in all cells but those next to an extremum, so it is second-order upwind
/// (docs/theory/dbm.md, "Smooth modes").
inline constexpr double kSmoothTheta = 0.7853981633974483;

struct StabilityReport {
  /// sup over all wave vectors of max Re λ(−i v·k + J), |k|τ in [1e-3, 1e4]: > 0 is an instability
  /// of the BGK model itself (continuous in space and time) at this state.
  double model_rate = 0.0;
  double model_k_tau = 0.0, model_angle = 0.0;  ///< |k|τ and the direction of k of model_rate
  /// max Re λ(−i S(k) + J) over the lattice's wave vectors: the growth rate of the discretised
  /// model as Δt → 0; > 0 means no time step makes the run stable.
  double semi_discrete_rate = 0.0;
  double theta_x = 0.0, theta_y = 0.0;  ///< kΔx, kΔy of semi_discrete_rate
  double amplification = 1.0;           ///< the largest ρ(G) per step
  double discrete_rate = 0.0;           ///< ln(amplification)/Δt, the growth rate of the run
  /// Largest Δt with no mode amplified by a step faster than it grows for Δt → 0 (bisection).
  double stable_dt = 0.0;
  /// With the first-order upwind stencil only: ln ρ(G)/Δt over the smooth modes (|θ| ≤ kSmoothTheta)
  /// with the second-order upwind stencil, and the θ of it (0 when not evaluated).
  double smooth_rate = 0.0;
  double smooth_theta_x = 0.0, smooth_theta_y = 0.0;
};

/// Growth rates below tolerance_rate(τ) count as neutral (the conserved modes at k → 0 are 0 to
/// round-off, the slowest decaying sound modes −O(k²τ)).
inline double tolerance_rate(double tau) { return 1e-6 / tau; }

StabilityReport analyse_stability(const StabilityProblem& problem, const Macro& state);

/// The temperatures around a stable T0 (ρ = 1, u = 0) for which the run (discrete = true) or the
/// model (false: model_rate) is stable, found by bisection to 1e-4 relative; assumes one interval
/// within [T0/1000, 1000 T0]. InputError-free: returns {T0, T0} when T0 itself is unstable.
struct TemperatureWindow {
  double low = 0.0, high = 0.0;
};
TemperatureWindow stable_temperatures(const StabilityProblem& problem, double T0, bool discrete);

/// A(k) = Δt(−i S(k) + J) for the wave vector θ = (kxΔx, kyΔy) (exposed for the tests).
ComplexMatrix16 step_matrix(const StabilityProblem& problem, const RealMatrix16& collision,
                            double theta_x, double theta_y, Stencil stencil);
/// J = −(I − ∂f^eq/∂f)/τ at `state`.
RealMatrix16 collision_jacobian(const StabilityProblem& problem, const Macro& state);

}  // namespace shockfield::dbm
