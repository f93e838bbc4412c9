#include "shockfield/dbm/gls_stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace shockfield::dbm {

GlsStepLimit gls_step_limit(const GlsSettings& gls, const Lattice& lattice, double max_speed,
                            double tau, double T, double rho_vapour, double rho_liquid) {
  constexpr double imaginary_axis = 1.7320508075688772;  // √3: RK3 stability on iℝ
  constexpr double real_axis = 2.5127453266183286;       // RK3 stability on −ℝ
  constexpr double filtered_k2 = 1.0 / 2.2;  // k_e²/k_N² of the twice-filtered operators
  const double k = std::numbers::pi / std::min(lattice.dx, lattice.dy);
  const double k2 = filtered_k2 * k * k;
  GlsStepLimit s;
  s.streaming = imaginary_axis / (max_speed * k);
  s.capillary = imaginary_axis / std::sqrt(k2 * (2.0 * T + gls.K * rho_liquid * k2));
  const double diffusivity = std::max(2.0 * T * (tau - gls.q), gls.zeta / rho_vapour);
  s.diffusion = real_axis / (diffusivity * k2);
  s.collision = real_axis * tau;
  s.dt = s.streaming, s.cause = "free streaming";
  if (s.capillary < s.dt) s.dt = s.capillary, s.cause = "capillary waves";
  if (s.diffusion < s.dt) s.dt = s.diffusion, s.cause = "diffusion";
  if (s.collision < s.dt) s.dt = s.collision, s.cause = "collision";
  return s;
}

double gls_mode_amplification(const StabilityProblem& problem, const Macro& state, double theta_x, double theta_y,
                              bool state_filter) {
  const RealMatrix16 J = collision_jacobian(problem, state);
  const ComplexMatrix16 collision = problem.dt * J.cast<std::complex<double>>();
  const double eta_x = std::abs(theta_x) / std::numbers::pi, eta_y = std::abs(theta_y) / std::numbers::pi;
  const ComplexMatrix16 A =
      collision + PeriodicSpectral::derivative_filter(eta_x, eta_y) *
                      (step_matrix(problem, J, theta_x, theta_y, Stencil::exact) - collision);
  const ComplexMatrix16 G = ComplexMatrix16::Identity() + A + A * A / 2.0 + A * A * A / 6.0;
  const double radius = Eigen::ComplexEigenSolver<ComplexMatrix16>(G, false).eigenvalues().cwiseAbs().maxCoeff();
  return state_filter ? radius * PeriodicSpectral::state_filter(eta_x, eta_y) : radius;
}

}  // namespace shockfield::dbm
