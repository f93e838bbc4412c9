// Detonation speed of the reactive DBM against Chapman–Jouguet theory at finer resolution and
// other rates and heat releases than the default-suite test (tests/unit/dbm/detonation_test.cpp):
// Δx = 0.005 (τ = 1e-3, Δt = Δx/10), fresh gas ρ0 = 1, p0 = 0.6, γ = 1.4. Each D within 2% of
// D_CJ (issue 6), and the Δx = 0.01 and 0.005 speeds within 0.5% of each other (converged).
// Label "slow" (about 3 × 1 min on one core): ctest --preset release -L slow.
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <cstdio>

#include "shockfield/dbm/detonation.hpp"

using namespace shockfield::dbm;

namespace {

DetonationTubeResult run(double Q, double rate, double activation, double dx) {
  DetonationTubeSetup d;
  d.law.heat_release = Q, d.law.rate = rate, d.law.activation = activation;
  d.law.ignition_temperature = 0.7;
  d.dx = dx, d.tau = 0.2 * dx, d.length = 6.0, d.t_end = 2.2;
  const DetonationTubeResult r = run_detonation_tube(d);
  std::printf("Q = %.2f, k = %g, Ea = %g, dx = %g: D = %.5f, D_CJ = %.5f (%+.2f%%)\n", Q, rate, activation, dx,
              r.speed, r.theory.speed, 100 * (r.speed / r.theory.speed - 1));
  return r;
}

}  // namespace

TEST(DbmDetonationSlow, SpeedConvergesToChapmanJouguet) {
  const DetonationTubeResult coarse = run(0.6, 20.0, 0.0, 0.01), fine = run(0.6, 20.0, 0.0, 0.005);
  EXPECT_NEAR(fine.speed, fine.theory.speed, 0.02 * fine.theory.speed);
  EXPECT_NEAR(fine.speed, coarse.speed, 0.005 * fine.speed);
}

TEST(DbmDetonationSlow, ArrheniusAndWeakerHeatRelease) {
  for (const auto& [Q, k, Ea] : {std::array<double, 3>{0.6, 200.0, 2.0}, std::array<double, 3>{0.3, 20.0, 0.0}}) {
    const DetonationTubeResult r = run(Q, k, Ea, 0.005);
    EXPECT_NEAR(r.speed, r.theory.speed, 0.02 * r.theory.speed) << "Q = " << Q;
  }
}
