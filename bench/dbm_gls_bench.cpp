// GLS liquid–vapour DBM benchmark: lattice-node updates per second of one RK3 step of the FFT-GLS
// model (spectral convection, the force of eqs. 14–18 with q and ζ, the state filter) on an n × n
// quench of the phase-separation example (Δx = 1/64 per cell, K = 6e-5), beside the compressible
// BGK model (D2V16, NND) on the same lattice and thread count. One thread count per call, so that
// runs can alternate (bench/RESULTS.md). Usage: dbm_gls_bench [n (512)] [steps (5)] [threads (1)].
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "shockfield/dbm/gls.hpp"
#include "shockfield/dbm/phase_separation.hpp"

using namespace shockfield::dbm;
using Clock = std::chrono::steady_clock;

namespace {

// Node-updates per second of `steps` steps after one warm-up step.
double rate(Simulation& sim, int steps) {
  sim.step();
  const auto t0 = Clock::now();
  for (int s = 0; s < steps; ++s) sim.step();
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return static_cast<double>(sim.lattice().nx) * sim.lattice().ny * steps / seconds;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 512;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 5;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  omp_set_num_threads(threads);
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice lattice;
  lattice.nx = lattice.ny = n;
  lattice.dx = lattice.dy = 1.0 / 64;
  Quench quench;
  quench.rho0 = 1.0, quench.T = 0.85, quench.noise = 0.05, quench.seed = 7;
  const QuenchNoise xi = quench.noise_field(lattice);
  const auto state = [&](double x, double y) { return quench.state(xi, x, y); };

  BgkSettings gls_bgk;
  gls_bgk.gamma = 2.0, gls_bgk.tau = 1e-3, gls_bgk.dt = 1e-3;
  gls_bgk.spectral_convection = gls_bgk.filter_state = true;
  Simulation gls_sim(model, lattice, Boundaries{}, gls_bgk);
  GlsSettings gls;
  gls.K = 6e-5, gls.q = -0.039, gls.zeta = 0.02;
  GlsForce force(gls_sim, Boundaries{}, gls);
  gls_sim.initialize(state);
  const double gls_rate = rate(gls_sim, steps);

  BgkSettings bgk;  // the compressible model as bench/dbm_bench runs it (γ = 1.4, NND)
  bgk.dt = 0.4 * lattice.dx / model.max_speed();
  bgk.tau = bgk.dt;
  Simulation bgk_sim(model, lattice, Boundaries{}, bgk);
  bgk_sim.initialize(state);
  const double bgk_rate = rate(bgk_sim, steps);
  std::printf("n %d threads %d steps %d: GLS %.4g node-updates/s, compressible BGK %.4g node-updates/s\n", n,
              threads, steps, gls_rate, bgk_rate);
}
