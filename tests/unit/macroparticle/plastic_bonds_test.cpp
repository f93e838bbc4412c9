// The plastic pair law of eq 16 (Fig 2) on one bond, in reduced units (r0 = D = 1, k = pq):
// continuity of tension and energy where the bond yields and where it unloads, unloading on the
// shifted elastic curve, reloading onto the route where it left it, energy = ∫ T dr along any
// path (the route's and the shifted curves' energies are consistent), breaking beyond the limit,
// and the table's round trip through a checkpoint vector.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/macroparticle/plastic_bonds.hpp"

namespace shockfield::macroparticle {
namespace {

const PlasticRoute kRoute{0.01, {0.1, 0.5}, 0.2};

struct Walk {
  PlasticBondLaw law{4, 9, kRoute};
  BondState s = law.initial();
  double t = 0, e = 0;
  void at(double r) { law.evaluate(r, s, t, e); }
};

TEST(MacroparticlePlasticBond, ElasticInsideTheBandAndContinuousAtYield) {
  Walk w;
  w.at(1.005);
  EXPECT_DOUBLE_EQ(w.t, w.law.elastic_tension(1.005));
  EXPECT_DOUBLE_EQ(w.s.shift, 0.0);
  w.at(1.01 - 1e-9);
  const double t_below = w.t, e_below = w.e;
  w.at(1.01 + 1e-9);
  EXPECT_NEAR(w.t, t_below, 1e-6);  // slopes k and 0.1k over 2e-9
  EXPECT_NEAR(w.e, e_below, 1e-9);
  EXPECT_GT(w.s.shift, 0.0);
}

TEST(MacroparticlePlasticBond, RouteFollowsItsPolynomialAndUnloadsOnTheShiftedCurve) {
  Walk w;
  for (double r = 1.0; r <= 1.03; r += 1e-4) w.at(r);
  const double ru = 1.03;
  w.at(ru);
  const double u = ru - 1.01;
  // T_P = T_E(r_y) + k (h1 u + h2 u²), k = 36.
  EXPECT_NEAR(w.t, w.law.elastic_tension(1.01) + 36.0 * (0.1 * u + 0.5 * u * u), 1e-12);
  const double t_route = w.t, e_route = w.e, shift = w.s.shift;
  EXPECT_NEAR(w.law.elastic_tension(ru - shift), t_route, 1e-12);  // Δr0 makes the force continuous
  // Unload: the shifted elastic curve φ_E(r − Δr0) + C_φ, continuous at r_u.
  w.at(ru - 1e-9);
  EXPECT_NEAR(w.t, t_route, 1e-6);
  EXPECT_NEAR(w.e, e_route, 1e-9);
  w.at(1.02);
  EXPECT_DOUBLE_EQ(w.s.shift, shift);
  EXPECT_NEAR(w.t, w.law.elastic_tension(1.02 - shift), 1e-14);
  // The tension vanishes at r0 + Δr0: the permanent set of the bond.
  w.at(1.0 + shift);
  EXPECT_NEAR(w.t, 0.0, 1e-12);
  // Reloading meets the route where it left it.
  w.at(ru);
  EXPECT_NEAR(w.t, t_route, 1e-9);
  EXPECT_NEAR(w.e, e_route, 1e-9);
}

TEST(MacroparticlePlasticBond, EnergyIsTheWorkOfTheTensionAlongAnyPath) {
  // Out along the route, back below r0 into the compression route, out again: the energy change
  // equals the trapezoid integral of T dr. Along a route the energy follows the curve the bond
  // came on, which differs from the route's tension by O(k h) within a step: an error of
  // O(k h²) per step, ~k h·(route length) ≈ 36·1e-5·0.1 = 4e-5 in all; allow 1e-4.
  Walk w;
  std::vector<double> path;
  for (double r = 1.0; r < 1.04; r += 1e-5) path.push_back(r);
  for (double r = 1.04; r > 0.97; r -= 1e-5) path.push_back(r);
  for (double r = 0.97; r < 1.02; r += 1e-5) path.push_back(r);
  w.at(path[0]);
  double work = 0, t_prev = w.t, e_start = w.e;
  for (std::size_t k = 1; k < path.size(); ++k) {
    w.at(path[k]);
    work += 0.5 * (w.t + t_prev) * (path[k] - path[k - 1]);
    t_prev = w.t;
  }
  EXPECT_NEAR(w.e - e_start, work, 1e-4);
  EXPECT_GT(std::abs(work), 0.01);
  EXPECT_LT(w.s.r_min, 0.99);   // it went through the compression route
  EXPECT_GT(w.s.r_max, 1.039);
}

// Saturation and a separate compression yield: the routes start at 1 + ε_y and 1 − ε_c, and past
// ε_s along a route its tension stays at T_P(ε_s) (a perfectly plastic bond).
TEST(MacroparticlePlasticBond, SaturatedRouteIsFlatAndTheCompressionRouteStartsAtItsOwnYield) {
  const PlasticRoute route{0.01, {0.1}, 0.2, 0.005, 0.03};
  const PlasticBondLaw law(4, 9, route);
  const double k = 36.0;
  auto walk = [&law](double from, double to, double dr) {
    BondState s = law.initial();
    double t = 0, e = 0;
    for (double r = from; dr > 0 ? r <= to : r >= to; r += dr) law.evaluate(r, s, t, e);
    law.evaluate(to, s, t, e);
    return std::pair{t, s};
  };
  const double t_sat = law.elastic_tension(1.01) + k * 0.1 * 0.005;
  EXPECT_NEAR(walk(1.0, 1.014, 1e-5).first, law.elastic_tension(1.01) + k * 0.1 * 0.004, 1e-12);  // before ε_s
  EXPECT_NEAR(walk(1.0, 1.02, 1e-5).first, t_sat, 1e-12);
  EXPECT_NEAR(walk(1.0, 1.05, 1e-5).first, t_sat, 1e-12);
  // Compression: elastic down to 1 − ε_c = 0.97 (beyond the tension side's 0.99), then the route.
  const auto [t_elastic, s_elastic] = walk(1.0, 0.975, -1e-5);
  EXPECT_EQ(s_elastic.shift, 0.0);
  EXPECT_DOUBLE_EQ(t_elastic, law.elastic_tension(0.975));
  const auto [t_route, s_route] = walk(1.0, 0.965, -1e-5);
  EXPECT_LT(s_route.shift, 0.0);
  EXPECT_NEAR(t_route, law.elastic_tension(0.97) - k * 0.1 * 0.005, 1e-12);
  EXPECT_NEAR(walk(1.0, 0.95, -1e-5).first, law.elastic_tension(0.97) - k * 0.1 * 0.005, 1e-12);  // saturated
}

TEST(MacroparticlePlasticBond, BreaksBeyondTheLimit) {
  Walk w;
  for (double r = 1.0; r < 1.25; r += 1e-3) w.at(r);
  EXPECT_TRUE(w.s.broken);
  const double e = w.e;
  w.at(1.05);
  EXPECT_EQ(w.t, 0.0);
  EXPECT_EQ(w.e, e);
}

TEST(MacroparticlePlasticBond, TableSurvivesACheckpointState) {
  BondTable a;
  a.pending(2)[1].emplace_back(BondTable::key(7, 3), BondState{0.01, -0.2, 1.03, 0.99, false, 1.03});
  a.apply_pending();
  a.pending(1)[0].emplace_back(BondTable::key(1, 4000000000LL), BondState{0.02, 0.1, 1.2, 0.99, true, -1});
  a.apply_pending();
  BondTable b;
  const md::FixState saved = a.state();
  ASSERT_EQ(saved.size(), 8u);
  EXPECT_EQ(saved[0].name, "bond_id_lo");
  EXPECT_EQ(saved[0].values, (std::vector<double>{1, 3}));  // sorted keys: (1, 4e9) before (3, 7)
  EXPECT_EQ(saved[1].values, (std::vector<double>{4000000000.0, 7}));
  b.restore(saved, "bond_history");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b.broken(), 1u);
  const BondState* s = b.find(BondTable::key(3, 7));
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->shift, 0.01);
  EXPECT_EQ(s->offset, -0.2);
  EXPECT_EQ(b.state().back().values, saved.back().values);
  // A state without one of the fields is refused naming it.
  md::FixState partial(saved.begin(), saved.end() - 1);
  try {
    b.restore(partial, "bond_history");
    FAIL() << "accepted a state without r_route";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no 'r_route'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shockfield::macroparticle
