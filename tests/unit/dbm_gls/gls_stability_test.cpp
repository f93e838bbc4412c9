// The time-step limit of the FFT-GLS model (gls_stability.hpp) against runs: a slab with seeded
// grid-scale noise stays bounded below the limit and blows up above it, for the limit set by
// capillary waves (large K) and by diffusion (large bulk viscosity ζ).
#include <gtest/gtest.h>


#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/dbm/gls_stability.hpp"
#include "unit/dbm_gls/gls_setup.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

// Runs `steps` steps at dt = factor × limit; true when the state stays finite and in the EOS domain.
bool survives(gls_testing::GlsCase c, double factor, int steps, GlsStepLimit& limit) {
  Lattice lattice;
  lattice.nx = c.nx, lattice.ny = c.ny, lattice.dx = lattice.dy = c.length / c.nx;
  GlsSettings gls;
  gls.K = c.K, gls.zeta = c.zeta;
  limit = gls_step_limit(gls, lattice, 4.0, c.tau, c.T, 0.4, 1.7);  // D2V16 max|v| = 4
  c.dt = factor * limit.dt;
  auto run = gls_testing::make_gls(c, [&](double x, double y) {
    const auto i = static_cast<std::uint64_t>(x * c.nx / c.length), j = static_cast<std::uint64_t>(y * c.nx / c.length);
    return Macro{1.0 + 0.3 * std::sin(6.283185307179586 * x) + 1e-3 * (rng::uniform(3, i, j) - 0.5), 0, 0, c.T};
  });
  try {
    for (int s = 0; s < steps; ++s) {
      run.sim->step();
      run.sim->check_state();
    }
  } catch (const RunError&) {
    return false;
  }
  return true;
}

}  // namespace

TEST(DbmGlsStability, CapillaryWaveLimit) {
  // K = 0.1 on 32² (Δx = 1/32): the capillary bound (4.1e-4·2.2) is far below the streaming and
  // collision bounds; stable at 0.9×, unstable at 2× (≈ 4.4× the unfiltered k_N bound).
  gls_testing::GlsCase c;
  c.nx = 32, c.ny = 32, c.length = 1.0, c.K = 0.1, c.tau = 5e-3, c.T = 0.95;
  GlsStepLimit limit;
  EXPECT_TRUE(survives(c, 0.9, 300, limit));
  EXPECT_EQ(limit.cause, "capillary waves");
  EXPECT_FALSE(survives(c, 2.0, 300, limit));
}

TEST(DbmGlsStability, DiffusionLimit) {
  // Bulk viscosity ζ = 10: ζ/ρ_v sets the bound; stable at 0.9×, unstable at 4× (≈ 8.8× unfiltered).
  gls_testing::GlsCase c;
  c.nx = 32, c.ny = 32, c.length = 1.0, c.K = 1e-4, c.zeta = 10.0, c.tau = 5e-3, c.T = 0.95;
  GlsStepLimit limit;
  EXPECT_TRUE(survives(c, 0.9, 300, limit));
  EXPECT_EQ(limit.cause, "diffusion");
  EXPECT_FALSE(survives(c, 4.0, 300, limit));
}
