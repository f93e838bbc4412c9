#pragma once
// A 1D Riemann problem (shock tube) run with the BGK DBM on an nx × 1 lattice with outflow ends,
// sampled against the exact solution (riemann_exact.hpp): the verification of the compressible
// model (Sod, Lax).
#include <vector>

#include "shockfield/dbm/riemann_exact.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

struct ShockTubeSetup {
  VelocityModel model;
  Primitive left, right;
  double gamma = 1.4;
  double length = 1.0, x0 = 0.5;  // tube [0, length], diaphragm at x0
  double t_end = 0.2;
  int nx = 200;
  double courant = 0.4;  // max|v| Δt/Δx
  double tau = 0.0;      // relaxation time; 0 means τ = Δt
};

struct ShockTubeResult {
  double time = 0.0;
  std::vector<double> x;
  std::vector<Primitive> dbm, exact;
  double l1_rho = 0.0, l1_u = 0.0, l1_p = 0.0;  // ∫|q − q_exact| dx / length
  /// Mean DBM value of ρ, u, p over the cells strictly inside (a, b).
  Primitive mean_over(double a, double b) const;
};

ShockTubeResult run_shock_tube(const ShockTubeSetup& setup);

}  // namespace shockfield::dbm
