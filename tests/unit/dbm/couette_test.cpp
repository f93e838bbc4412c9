// Thermal Couette flow between an isothermal wall at rest (y = 0) and one moving at u0 (y = H):
// the viscosity and Prandtl number of the BGK DBM.
//  - Start-up: u − u0 y/H decays mode by mode; the first mode as exp(−π² ν t / H²) gives
//    ν = μ/ρ, Chapman–Enskog μ = τ ρ T (here ρ = T = 1, so ν = τ).
//  - Steady state: T = T0 + Pr u0²/(2 c_p) · ξ(1 − ξ), ξ = y/H, c_p = (b+2)/2; BGK gives Pr = 1.
// Tolerance 3%: the NND scheme adds a numerical viscosity falling as Δy² (measured ν/τ − 1:
// 4.6% at 40 cells, 1.4% at 80), and Kn = τc/H = 5e-3 gives wall slip and temperature jumps of
// order Kn. Measured at 80 cells: ν = 1.014 τ, Pr = 1.0125.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "shockfield/dbm/simulation.hpp"

using namespace shockfield::dbm;

TEST(DbmCouette, ViscosityAndPrandtlNumber) {
  const double pi = std::numbers::pi, u0 = 0.5;
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = 1;
  l.ny = 80;
  l.dx = l.dy = 1.0 / l.ny;
  Boundaries bc;
  bc.side[2].kind = bc.side[3].kind = BoundaryKind::wall;
  bc.side[2].state = {1.0, 0.0, 0.0, 1.0};
  bc.side[3].state = {1.0, u0, 0.0, 1.0};
  BgkSettings s;
  s.dt = 0.4 * l.dy / model.max_speed();
  s.tau = 5e-3;
  Simulation sim(model, l, bc, s);
  sim.initialize([](double, double) { return Macro{1.0, 0.0, 0.0, 1.0}; });

  // First sine mode of the departure from the linear profile.
  auto mode = [&] {
    double a = 0;
    for (int j = 0; j < l.ny; ++j) {
      const double xi = l.y(j);
      a += 2.0 * (sim.macro(0, j).ux - u0 * xi) * std::sin(pi * xi) * l.dy;
    }
    return a;
  };
  auto run_until = [&](double t) {
    while (sim.time() < t - 1e-12) sim.step();
  };
  run_until(2.0);
  const double t1 = sim.time(), a1 = mode();
  run_until(6.0);
  const double t2 = sim.time(), a2 = mode();
  const double nu = -std::log(a2 / a1) / (pi * pi * (t2 - t1));

  run_until(60.0);
  sim.check_state();
  // Least-squares amplitude of T − 1 on ξ(1 − ξ).
  double num = 0, den = 0;
  for (int j = 0; j < l.ny; ++j) {
    const double shape = l.y(j) * (1 - l.y(j));
    num += (sim.macro(0, j).T - 1.0) * shape;
    den += shape * shape;
  }
  const double cp = (sim.b() + 2) / 2;
  const double prandtl = num / den * 2 * cp / (u0 * u0);
  std::printf("nu = %.5f (tau = %.5f), Pr = %.4f\n", nu, s.tau, prandtl);
  EXPECT_NEAR(nu, s.tau, 0.03 * s.tau);
  EXPECT_NEAR(prandtl, 1.0, 0.03);
}
