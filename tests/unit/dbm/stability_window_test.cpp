// The stable temperature windows of the D2V16 speed sets of the examples and tests, as tabulated
// in docs/theory/dbm.md ("Stable temperature windows"): computed with stable_temperatures()
// (linear_stability.hpp) at ρ = 1, u = 0 and checked against the table (~2 s).
//   OMP_NUM_THREADS=1 build/release/tests/test_dbm --gtest_filter='DbmStabilityWindow.*'
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "shockfield/dbm/linear_stability.hpp"

namespace shockfield::dbm {
namespace {

struct Row {
  const char* name;
  std::array<double, 4> speeds;
  double eta0, tau, dx, dt, T0;
  TemperatureWindow run, model;  // as documented
};

TEST(DbmStabilityWindow, MatchesTheTable) {
  const Row rows[] = {
      {"Sod example (speeds 1..4)", {1, 2, 3, 4}, 2.0, 2.5e-4, 0.0025, 2.5e-4, 1.0, {0.5412, 1.327}, {0.4711, 1.125}},
      {"detonation example (speeds 1..4)", {1, 2, 3, 4}, 2.0, 2e-3, 0.01, 1e-3, 1.0, {0.5182, 1.256}, {0.4711, 1.125}},
      {"Lax test (speeds 3, 2, 5, 10)", {3, 2, 5, 10}, 8.0, 1e-4, 0.0025, 1e-4, 3.0, {0.1043, 19.83}, {1.097, 9.09}},
  };
  for (const Row& row : rows) {
    StabilityProblem p;
    p.model = d2v16(row.speeds, row.eta0);
    p.b = 5.0, p.tau = row.tau, p.dx = p.dy = row.dx, p.dt = row.dt;
    p.two_dimensional = false;
    const TemperatureWindow run = stable_temperatures(p, row.T0, true);
    const TemperatureWindow model = stable_temperatures(p, row.T0, false);
    std::printf("| %s | %.4g–%.4g | %.4g–%.4g |\n", row.name, run.low, run.high, model.low, model.high);
    EXPECT_NEAR(run.low, row.run.low, 1e-3 * row.run.low) << row.name;
    EXPECT_NEAR(run.high, row.run.high, 1e-3 * row.run.high) << row.name;
    EXPECT_NEAR(model.low, row.model.low, 1e-3 * row.model.low) << row.name;
    EXPECT_NEAR(model.high, row.model.high, 1e-3 * row.model.high) << row.name;
  }
}

}  // namespace
}  // namespace shockfield::dbm
