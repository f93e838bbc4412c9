// Dukowicz's two-shock interface pressure (Liu et al. 2025, eq. 15).
#include <gtest/gtest.h>

#include "shockfield/pd/riemann.hpp"

using namespace shockfield::pd;

// Equal states: the interface keeps them.
TEST(Riemann, EqualStatesAreKept) {
  const RiemannSide s{1e8, 12.0, 2700.0, 6000.0, 1.3};
  const auto r = dukowicz_two_shock(s, s);
  EXPECT_NEAR(r.p, 1e8, 1e-6);
  EXPECT_NEAR(r.u, 12.0, 1e-12);
}

// s = 0: the acoustic solution p* = (Z_R p_L + Z_L p_R + Z_L Z_R (u_L − u_R)) / (Z_L + Z_R).
TEST(Riemann, AcousticLimit) {
  const RiemannSide l{2e8, 40.0, 2700.0, 6000.0, 0.0}, r{-1e8, -10.0, 8900.0, 4700.0, 0.0};
  const double zl = 2700.0 * 6000.0, zr = 8900.0 * 4700.0;
  const double expected = (zr * l.p + zl * r.p + zl * zr * (l.u - r.u)) / (zl + zr);
  EXPECT_NEAR(dukowicz_two_shock(l, r).p, expected, 1e-9 * std::abs(expected));
}

// Symmetric impact at ±v: u* = 0 and p* = p0 + ρ(a + s·v)·v, the Hugoniot of the linear Us-Up law.
TEST(Riemann, SymmetricImpactFollowsTheHugoniot) {
  for (double v : {10.0, 300.0, 3000.0}) {
    const RiemannSide l{0.0, v, 8930.0, 3940.0, 1.49}, r{0.0, -v, 8930.0, 3940.0, 1.49};
    const auto sol = dukowicz_two_shock(l, r);
    EXPECT_NEAR(sol.u, 0.0, 1e-9 * v);
    EXPECT_NEAR(sol.p, 8930.0 * (3940.0 + 1.49 * v) * v, 1e-9 * sol.p) << v;
  }
}

// Any states: both Hugoniots give the same p* at u* (the equation is solved exactly), also
// for separating sides (tension) and unequal materials.
TEST(Riemann, BothSidesAgreeAtTheInterface) {
  const RiemannSide cases[][2] = {{{1e9, 100.0, 2700, 5300, 1.34}, {-2e8, -50.0, 8930, 3940, 1.49}},
                                  {{0.0, -80.0, 2700, 5300, 1.34}, {3e8, 90.0, 8930, 3940, 1.49}},
                                  {{5e8, 0.0, 2700, 5300, 1.34}, {5e8, 0.0, 19300, 4000, 1.2}}};
  for (const auto& c : cases) {
    const RiemannSide &l = c[0], &r = c[1];
    const auto sol = dukowicz_two_shock(l, r);
    const double from_left = l.p - l.rho * (l.a + l.s * std::abs(sol.u - l.u)) * (sol.u - l.u);
    EXPECT_NEAR(sol.p, from_left, 1e-9 * std::max(std::abs(sol.p), 1e6));
  }
}
