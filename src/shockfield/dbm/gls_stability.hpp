#pragma once
// Largest stable time step of the FFT-GLS model (Xu et al. 2015, eqs. 13–18) under third-order
// Runge–Kutta, from the linear modes at the largest resolved wavenumber k_N = π/Δx:
//   free streaming (spectral v·∇f):       λ = i v_max k_N
//   capillary (Korteweg) waves:           λ = i k_e sqrt(c² + Kρ_l k_e²),  c² = 2T (γ = 2)
//   heat conduction, bulk viscosity:      λ = −D k_e², D = max(2T(τ − q), ζ/ρ_v)
//   BGK collision:                        λ = −1/τ
// RK3 is stable for |λ|Δt ≤ √3 on the imaginary and ≤ 2.51 on the negative real axis. The
// second-derivative terms pass the spectral filter exp(−36η⁸) twice, which lowers their largest
// effective k² to k_e² = k_N²/2.2: runs blow up at 3–4× (capillary) and 6–8× (diffusion) the
// bounds computed with k_N (tests/unit/dbm_gls/gls_stability_test.cpp), so k_N²/2.2 keeps a margin
// of ≥ 1.4. The tightest bound is reported with its cause, so an unstable Δt is refused with
// a reason (docs/theory/dbm.md, "Time-step limit").
#include <string>

#include "shockfield/dbm/gls.hpp"
#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/linear_stability.hpp"

namespace shockfield::dbm {

struct GlsStepLimit {
  double dt = 0.0;        ///< the largest stable Δt (the smallest of the four bounds)
  std::string cause;      ///< "free streaming", "capillary waves", "diffusion" or "collision"
  double streaming = 0.0, capillary = 0.0, diffusion = 0.0, collision = 0.0;  ///< each bound
};

/// The bounds for densities up to rho_liquid and down to rho_vapour at temperature T.
GlsStepLimit gls_step_limit(const GlsSettings& gls, const Lattice& lattice, double max_speed,
                            double tau, double T, double rho_vapour, double rho_liquid);

/// Per-step amplification ρ(G) of a mode θ = (k_xΔx, k_yΔy) of the FFT-GLS scheme linearised about
/// the uniform `state` (problem.stencil is ignored): G = I + A + A²/2 + A³/6 with
/// A = Δt(−iσ_d(θ) v·k + J), σ_d the derivative filter, times the state filter σ_s(θ) when
/// `state_filter` is on. The GLS force is made of filtered derivatives and vanishes with σ_d, so
/// beyond θ ≈ 0.8π (σ_d < 1e-3) A → ΔtJ, whose four conserved moments have eigenvalue 0: without
/// the state filter ρ(G) = 1 there, the undamped band (docs/theory/dbm.md).
double gls_mode_amplification(const StabilityProblem& problem, const Macro& state, double theta_x, double theta_y,
                              bool state_filter);

}  // namespace shockfield::dbm
