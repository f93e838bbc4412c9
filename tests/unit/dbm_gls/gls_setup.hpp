#pragma once
// Shared set-up of the GLS liquid–vapour tests: a periodic D2V16 simulation (γ = 2) with the
// GLS force term, the van der Waals EOS of the paper (a = 9/8, b = 1/3, T_c = ρ_c = 1).
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include "shockfield/dbm/gls.hpp"

namespace shockfield::dbm::gls_testing {

struct GlsCase {
  int nx = 128, ny = 4;
  double length = 1.0;  // domain length along x (dx = length/nx = dy)
  double tau = 0.01, dt = 1e-3, K = 1e-4, zeta = 0.0, q = 0.0;
  double T = 0.9;
  bool spectral = true;
  bool filter_state = false;  // the state filter (the case files' default for GLS is on)
  std::array<double, 4> speeds{1.0, 2.0, 3.0, 4.0};  // D2V16 speeds, eta0 = 2
  GlsEos eos = materials::VanDerWaals{};
};

struct GlsRun {
  std::unique_ptr<Simulation> sim;
  std::unique_ptr<GlsForce> force;
};

inline GlsRun make_gls(const GlsCase& c, const std::function<Macro(double, double)>& state) {
  Lattice lattice;
  lattice.nx = c.nx, lattice.ny = c.ny;
  lattice.dx = lattice.dy = c.length / c.nx;
  Boundaries periodic;
  BgkSettings bgk;
  bgk.gamma = 2.0, bgk.tau = c.tau, bgk.dt = c.dt, bgk.spectral_convection = c.spectral;
  bgk.filter_state = c.filter_state;
  GlsRun run;
  run.sim = std::make_unique<Simulation>(d2v16(c.speeds, 2.0), lattice, periodic, bgk);
  GlsSettings gls;
  gls.eos = c.eos, gls.K = c.K, gls.zeta = c.zeta, gls.q = c.q;
  run.force = std::make_unique<GlsForce>(*run.sim, periodic, gls);
  run.sim->initialize(state);
  return run;
}

}  // namespace shockfield::dbm::gls_testing
