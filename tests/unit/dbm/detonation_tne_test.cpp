// The detonation TNE study in small (examples/dbm_detonation/README.md, "TNE against viscosity";
// Xu et al. 2015, §4.3): the slow-reaction detonation (k = 1, zone ≈ 0.7) at Δx = 0.01 with
// τ = 0.01 and 0.02, where the shock ahead of the von Neumann peak (width ≈ 11 τ) spans 11 and
// 22 cells. Checked: the global TNE ∫|Δ*_2xx| dx over the wave (from 0.6 behind the pressure
// peak to the fresh gas, tests/support/detonation_tne.hpp) grows with τ, and Δ*_2xx changes
// sign ahead of the pressure peak, inside the resolved shock, not at the peak. The resolution
// study behind these numbers is DbmDetonationSlow.TneCrossingConvergesWithTheGrid (label slow).
// About 2 s of CPU.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/detonation_tne.hpp"

using namespace shockfield;

namespace {

test::DetonationTne run(double tau) {
  dbm::DetonationTubeSetup d;
  d.law.heat_release = 0.6, d.law.rate = 1.0, d.law.ignition_temperature = 0.7;
  d.length = 4.0, d.dx = 0.01, d.tau = tau, d.t_end = 1.5, d.ignition_width = 0.7;
  const test::DetonationTne m = test::detonation_tne(dbm::run_detonation_tube(d));
  std::printf("tau %g: shock %.1f cells, D*2xx = 0 at %+.2f cells (%+.3f widths) from the p peak, "
              "max D*2xx %.4f, at the peak %+.4f, global %.5f\n",
              tau, m.width_cells, m.zero_cells, m.zero_widths, m.local_max, m.at_peak, m.global);
  return m;
}

}  // namespace

TEST(DbmDetonationTne, GlobalTneGrowsWithTauAndTheSignChangeLiesAheadOfThePeak) {
  const test::DetonationTne a = run(0.01), b = run(0.02);
  for (const auto* m : {&a, &b}) {
    ASSERT_GE(m->width_cells, 10.0) << "the shock is resolved (the premise of the study)";
    // Measured +0.64 and +0.55 widths here, +0.65 to +0.53 at Δx = 0.0025 for τ = 0.0025 … 0.02;
    // a crossing at the peak (the paper's picture) or inside an unresolved shock would give
    // |zero| < 0.1 widths or < 3 cells.
    EXPECT_GT(m->zero_widths, 0.4) << "Δ*_2xx = 0 ahead of the pressure peak, in the shock";
    EXPECT_GT(m->zero_cells, 5.0) << "Δ*_2xx = 0 resolved by the grid";
    EXPECT_LT(m->at_peak, -0.2 * m->local_max) << "not near equilibrium at the peak";
  }
  // Δ* ∝ τ × gradients, and the reaction zone's length (≈ D/k) does not depend on τ: the
  // integral over the wave doubles with τ (measured ×2.00); 1.5 leaves room for the different
  // decay of the overdriven start at the two τ.
  EXPECT_GT(b.global, 1.5 * a.global) << "global TNE grows with viscosity / heat conductivity";
}
