// Slow study (label slow): Young's modulus of the rod of Saitoh et al. converging with division
// (Fig 4). The rod's E approaches the modulus of its packing along [001], E_001 = (2√2/3) k/r0
// (docs/theory/macroparticle.md §2), as 1/n_phi (the share of surface particles with missing
// bonds), so the Richardson extrapolation 2E(2n) − E(n) from n_phi = 4 and 8 is the converged
// value; it must be within 3 % of E_001 — and therefore 1.886 times eq 15, not eq 15.
#include <gtest/gtest.h>

#include <numbers>

#include "unit/macroparticle/rod_fixture.hpp"

namespace shockfield::macroparticle {
namespace {

TEST(MacroparticleRodSlow, YoungsModulusConvergesWithDivisionToTheLatticeValue) {
  const auto coarse = fixture::elastic_fit(4, 8, 4000);
  const auto fine = fixture::elastic_fit(8, 16, 4000);
  const double e001 = fine.law.youngs_lattice_001();
  EXPECT_GT(fine.youngs, coarse.youngs);
  EXPECT_NEAR((2.0 * fine.youngs - coarse.youngs) / e001, 1.0, 0.03)
      << "E(4) = " << coarse.youngs << ", E(8) = " << fine.youngs << ", E_001 = " << e001;
  EXPECT_NEAR(e001 / fine.law.youngs_eq15(), 4.0 * std::numbers::sqrt2 / 3.0, 1e-12);
  // Poisson's ratio approaches the lattice's 1/3 from above.
  EXPECT_LT(fine.poisson, coarse.poisson + 0.002);
  EXPECT_NEAR(fine.poisson, 1.0 / 3.0, 0.02);
}

}  // namespace
}  // namespace shockfield::macroparticle
