// DBM inflow sides: the characteristic (subsonic_inflow) ghost state against the Riemann
// invariants of the 1D Euler equations, the reflection of an acoustic pulse by the inflow and the
// subsonic_inflow sides, and a shock driven by either at the von Neumann state running at the
// Rankine–Hugoniot speed (docs/theory/dbm.md, "Inflow boundaries").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/detonation.hpp"
#include "shockfield/dbm/simulation.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

constexpr double kGamma = 1.4;

// u_n ± 2c/(γ−1) and p/ρ^γ of a state seen from a side (u_n: velocity into the domain).
struct Characteristics {
  double j_in, j_out, entropy;
};
Characteristics characteristics(const Macro& m, int axis, bool high) {
  const double un = (high ? -1.0 : 1.0) * (axis == 0 ? m.ux : m.uy);
  const double k = 2.0 / (kGamma - 1.0) * std::sqrt(kGamma * m.T);
  return {un + k, un - k, m.T / std::pow(m.rho, kGamma - 1.0)};
}

// The state on the isentrope of `m` with the same J_in whose sound speed is c_new: a finite
// outgoing simple wave of m.
Macro outgoing_simple_wave(const Macro& m, int axis, bool high, double c_ratio) {
  const Characteristics ch = characteristics(m, axis, high);
  const double c = std::sqrt(kGamma * m.T) * c_ratio;
  const double un = ch.j_in - 2.0 / (kGamma - 1.0) * c;
  Macro w = m;
  w.T = c * c / kGamma;
  w.rho = std::pow(w.T / ch.entropy, 1.0 / (kGamma - 1.0));
  (axis == 0 ? w.ux : w.uy) = (high ? -1.0 : 1.0) * un;
  return w;
}

// Amplitudes of the right- and left-going acoustic waves, (δp ± ρc δu)/2, largest over the row.
struct Waves {
  double right = 0.0, left = 0.0;
};
Waves acoustic_waves(const Simulation& sim, const Macro& base) {
  const double c = std::sqrt(kGamma * base.T);
  Waves w;
  for (int i = 0; i < sim.lattice().nx; ++i) {
    const Macro m = sim.macro(i, 0);
    const double dp = m.rho * m.T - base.rho * base.T, du = m.ux - base.ux;
    w.right = std::max(w.right, std::abs(0.5 * (dp + base.rho * c * du)));
    w.left = std::max(w.left, std::abs(0.5 * (dp - base.rho * c * du)));
  }
  return w;
}

// A left-going Gaussian pressure pulse (δp = 1e-3 p, δu = −δp/(ρc), δρ = δp/c²) at x = 0.6 in a
// stream ρ = T = 1, u = 0.3 (Mach 0.25) on [0, 2], Δx = 0.01, fed through x_low of `kind`.
// Returns reflected / incident amplitude: the right-going wave after the pulse has met the side
// over the left-going one just before.
double reflection_coefficient(BoundaryKind kind) {
  const Macro base{1.0, 0.3, 0.0, 1.0};
  const double c = std::sqrt(kGamma * base.T), x0 = 0.6, width = 0.08;
  Lattice l;
  l.nx = 200, l.dx = l.dy = 0.01;
  Boundaries bc;
  bc.side[0] = {kind, base};
  bc.side[1].kind = BoundaryKind::outflow;
  BgkSettings s;
  s.gamma = kGamma, s.dt = 0.1 * l.dx, s.tau = 2e-3;
  Simulation sim(d2v16({1.0, 2.0, 3.0, 4.0}, 2.0), l, bc, s);
  sim.initialize([&](double x, double) {
    const double dp = 1e-3 * std::exp(-std::pow((x - x0) / width, 2));
    const double drho = dp / (c * c);
    return Macro{base.rho + drho, base.ux - dp / (base.rho * c), 0.0, (base.rho * base.T + dp) / (base.rho + drho)};
  });
  const double arrival = (x0 - 3 * width) / (c - base.ux);  // pulse 3 widths from the side
  const double reflected = x0 / (c - base.ux) + 0.8 / (c + base.ux);  // the echo 0.8 inside
  while (sim.time() < arrival) sim.step();
  const double incident = acoustic_waves(sim, base).left;
  while (sim.time() < reflected) sim.step();
  sim.check_state();
  return acoustic_waves(sim, base).right / incident;
}

}  // namespace

TEST(DbmBoundary, SubsonicInflowStateTakesIncomingInvariantsFromTheImposedState) {
  for (int side = 0; side < 4; ++side) {
    const int axis = side / 2;
    const bool high = side % 2 == 1;
    Macro in{1.3, 0.0, 0.0, 0.9};  // entering at 0.4 (Mach 0.38) with a tangential -0.1
    (axis == 0 ? in.ux : in.uy) = high ? -0.4 : 0.4;
    (axis == 0 ? in.uy : in.ux) = -0.1;
    // The fluid at the imposed state: the ghost is that state.
    const Macro same = subsonic_inflow_state(in, in, axis, high, kGamma);
    EXPECT_NEAR(same.rho, in.rho, 1e-13);
    EXPECT_NEAR(same.ux, in.ux, 1e-13);
    EXPECT_NEAR(same.uy, in.uy, 1e-13);
    EXPECT_NEAR(same.T, in.T, 1e-13);
    // A finite outgoing simple wave of the imposed state passes unchanged (no reflection).
    const Macro wave = outgoing_simple_wave(in, axis, high, 1.1);
    const Macro passed = subsonic_inflow_state(in, wave, axis, high, kGamma);
    EXPECT_NEAR(passed.rho, wave.rho, 1e-12) << "side " << side;
    EXPECT_NEAR(passed.ux, wave.ux, 1e-12) << "side " << side;
    EXPECT_NEAR(passed.uy, wave.uy, 1e-12) << "side " << side;
    EXPECT_NEAR(passed.T, wave.T, 1e-12) << "side " << side;
    // Any fluid state: J_in, entropy and tangential velocity imposed, J_out from the fluid.
    const Macro fluid{2.0, 0.1, 0.3, 1.2};
    const Macro ghost = subsonic_inflow_state(in, fluid, axis, high, kGamma);
    const Characteristics g = characteristics(ghost, axis, high), i = characteristics(in, axis, high),
                          f = characteristics(fluid, axis, high);
    EXPECT_NEAR(g.j_in, i.j_in, 1e-12);
    EXPECT_NEAR(g.entropy, i.entropy, 1e-12);
    EXPECT_NEAR(g.j_out, f.j_out, 1e-12);
    EXPECT_EQ(axis == 0 ? ghost.uy : ghost.ux, -0.1) << "tangential velocity imposed";
    // Fluid rushing in so fast that J_out ≥ J_in: no state with c > 0, the run stops.
    Macro rushing = fluid;
    (axis == 0 ? rushing.ux : rushing.uy) = high ? -20.0 : 20.0;
    EXPECT_THROW(subsonic_inflow_state(in, rushing, axis, high, kGamma), RunError);
  }
}

TEST(DbmBoundary, SubsonicInflowRefusesStatesThatDoNotEnterSubsonically) {
  const double c = std::sqrt(kGamma * 1.0);
  EXPECT_NO_THROW(check_subsonic_inflow({1.0, 0.5, 0.0, 1.0}, 0, false, kGamma));
  EXPECT_NO_THROW(check_subsonic_inflow({1.0, -0.5, 0.0, 1.0}, 0, true, kGamma));
  for (const Macro& bad : {Macro{1.0, 0.0, 0.0, 1.0}, Macro{1.0, -0.5, 0.0, 1.0}, Macro{1.0, 1.01 * c, 0.0, 1.0}}) {
    try {
      check_subsonic_inflow(bad, 0, false, kGamma);
      FAIL() << "u = " << bad.ux << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("slower than sound"), std::string::npos) << e.what();
    }
  }
  Boundaries b;
  b.side[0] = {BoundaryKind::subsonic_inflow, {1.0, 2.0, 0.0, 1.0}};  // Mach 1.7: use inflow
  b.side[1].kind = BoundaryKind::outflow;
  Lattice l;
  l.nx = 10, l.dx = l.dy = 0.1;
  BgkSettings s;
  s.dt = 0.01, s.tau = 0.01;
  EXPECT_THROW(Simulation(d2v16({1.0, 2.0, 3.0, 4.0}, 2.0), l, b, s), InputError);
  EXPECT_EQ(boundary_kind("subsonic_inflow"), BoundaryKind::subsonic_inflow);
}

TEST(DbmBoundary, SubsonicInflowReflectsAnAcousticPulseFarLessThanInflow) {
  // Measured: inflow 0.099, subsonic_inflow 0.0025 (the rest is the start-up of the pulse).
  const double fixed = reflection_coefficient(BoundaryKind::inflow);
  const double characteristic = reflection_coefficient(BoundaryKind::subsonic_inflow);
  std::printf("acoustic reflection coefficient: inflow %.4f, subsonic_inflow %.4f\n", fixed, characteristic);
  EXPECT_GT(fixed, 0.05) << "the fixed-f^eq inflow side reflects part of an arriving wave";
  EXPECT_LT(characteristic, 0.01);
}

TEST(DbmBoundary, ShockDrivenByVonNeumannInflowRunsAtRankineHugoniotSpeed) {
  // Gas at rest (ρ = 1, p = 0.6) fed at x = 0 with the von Neumann state of the CJ detonation for
  // Q = 0.6 (inert: no reaction): a shock at D_CJ, started impulsively, Δx = 0.005, front fitted
  // over t in [0.5, 1]. Measured: 0.00% (subsonic_inflow), −0.01% (inflow).
  const ChapmanJouguet cj = chapman_jouguet({1.0, 0.0, 0.6}, kGamma, 0.6);
  const GasState& vn = cj.von_neumann;
  for (BoundaryKind kind : {BoundaryKind::subsonic_inflow, BoundaryKind::inflow}) {
    Lattice l;
    l.nx = 400, l.dx = l.dy = 0.005;
    Boundaries bc;
    bc.side[0] = {kind, {vn.rho, vn.u, 0.0, vn.p / vn.rho}};
    bc.side[1].kind = BoundaryKind::outflow;
    BgkSettings s;
    s.gamma = kGamma, s.dt = 0.1 * l.dx, s.tau = 2e-3;
    Simulation sim(d2v16({1.0, 2.0, 3.0, 4.0}, 2.0), l, bc, s);
    sim.initialize([](double, double) { return Macro{1.0, 0.0, 0.0, 0.6}; });
    std::vector<double> t, front;
    for (int n = 1; n <= 2000; ++n) {
      sim.step();
      if (n % 20 == 0 && n >= 1000) {
        t.push_back(sim.time());
        front.push_back(pressure_front(sim, 0, 0.5 * (0.6 + vn.p)));
      }
    }
    sim.check_state();
    const double D = fitted_speed(t, front);
    std::printf("%s: D = %.5f, Rankine-Hugoniot %.5f (%+.2f%%)\n",
                kind == BoundaryKind::inflow ? "inflow" : "subsonic_inflow", D, cj.speed, 100 * (D / cj.speed - 1));
    EXPECT_NEAR(D, cj.speed, 0.005 * cj.speed);
  }
}
