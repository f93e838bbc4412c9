// The 1D travelling front of ∂ₜξ = −f′(ξ) + D∇²ξ against its closed form (Nagumo wave,
// docs/theory/phasefield.md): speed c₀ = √(D/2)(1 − 2a) and profile [1 − tanh(d/(2√(2D)))]/2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shockfield/phasefield/initial.hpp"
#include "shockfield/phasefield/solver.hpp"

namespace shockfield::phasefield {
namespace {

struct FrontRun {
  double speed;        // measured growth speed of the hcp slab's fronts
  double profile_err;  // max |ξ − tanh profile| at the end
};

// A slab of hcp (half width 20 l, l = √(2D)) in a periodic line of 80 l; both fronts move out
// at c₀, so d(Σ ξ dx)/dt = 2c₀. The slope is fitted (least squares) over the second half of a run
// in which each front moves 8 l (the first half lets the discrete front settle).
FrontRun run_front(Scheme scheme, double a, double D, int nodes_per_length, double dt_factor) {
  const Model model{a, D};
  const double l = model.front_length();
  Grid grid{1, {80 * nodes_per_length, 1, 1}, l / nodes_per_length};
  const double dt = dt_factor * grid.explicit_limit(D);
  Solver solver(grid, model, scheme, dt);
  const double half = 20 * l, center = 40 * l;
  solver.field() = initial_field(grid, model, {Domain{Domain::Kind::slab, {center, 0, 0}, {half, 0, 0}, {1, 0, 0}}});
  const double c0 = model.front_speed();
  const auto steps = static_cast<long>(std::ceil(8 * l / std::abs(c0) / dt));
  double st = 0, sy = 0, stt = 0, sty = 0;
  long count = 0;
  for (long s = 1; s <= steps; ++s) {
    solver.step();
    if (2 * s > steps) {
      const double t = solver.time(), y = solver.measures().integral;
      st += t, sy += y, stt += t * t, sty += t * y;
      ++count;
    }
  }
  const double slope = (count * sty - st * sy) / (count * stt - st * st);
  // The right front: the ξ = 1/2 crossing by linear interpolation, then the profile about it.
  const std::vector<double>& xi = solver.field();
  double front = 0;
  for (int i = grid.n[0] / 2; i + 1 < grid.n[0]; ++i)
    if (xi[i] >= 0.5 && xi[i + 1] < 0.5) {
      front = (i + (xi[i] - 0.5) / (xi[i] - xi[i + 1])) * grid.dx;
      break;
    }
  double err = 0;
  for (int i = grid.n[0] / 2; i < grid.n[0]; ++i)
    err = std::max(err, std::abs(xi[i] - model.profile(i * grid.dx - front)));
  return {slope / 2, err};
}

// Explicit scheme at dt = dx²/(4D) (half the limit), so the time error shrinks with dx² too.
// Tolerance 0.5 % at l/dx = 16 (the requirement; measured 1.0e-4 … 2.1e-4); the observed
// order must be 2 ± 0.1 (second-order Laplacian, first-order Euler at dt ∝ dx²; measured 2.00).
TEST(PhasefieldFront, SpeedMatchesClosedFormWithSecondOrderConvergence) {
  for (const double a : {0.1, 0.25, 0.4, 0.7})
    for (const double D : {0.5, 2.0}) {
      const double c = Model{a, D}.front_speed();
      double previous = 0;
      for (const int m : {4, 8, 16}) {
        const double error = std::abs(run_front(Scheme::explicit_euler, a, D, m, 0.5).speed / c - 1);
        if (previous > 0) {
          const double order = std::log2(previous / error);
          EXPECT_NEAR(order, 2.0, 0.1) << "a " << a << " D " << D << " l/dx " << m << " error " << error;
          RecordProperty(fmt::format("order_a{}_D{}_m{}", a, D, m), fmt::format("{:.3f}", order));
        }
        if (m == 16) {
          EXPECT_LT(error, 5e-3) << "a " << a << " D " << D;
          RecordProperty(fmt::format("error_a{}_D{}", a, D), fmt::format("{:.2e}", error));
        }
        previous = error;
      }
    }
}

// The profile about the half-level crossing: the tanh form to 2e-4 at l/dx = 16 (max error over
// the front half of the line; measured 3e-5 … 4e-5).
TEST(PhasefieldFront, ProfileIsTanh) {
  for (const double a : {0.25, 0.4}) {
    const FrontRun run = run_front(Scheme::explicit_euler, a, 1.0, 16, 0.5);
    EXPECT_LT(run.profile_err, 2e-4) << "a " << a;
    RecordProperty(fmt::format("profile_error_a{}", a), fmt::format("{:.2e}", run.profile_err));
  }
}

// The semi-implicit spectral scheme: exact in space, first order in time. At dt = dx²/(8D)
// (a quarter of the explicit limit), l/dx = 8, its speed matches the closed form within 0.5 %
// (measured −0.04 %, the O(dt) splitting error).
TEST(PhasefieldFront, SpectralSpeedMatchesClosedForm) {
  for (const double a : {0.25, 0.4}) {
    const double c = Model{a, 1.0}.front_speed();
    const double ratio = run_front(Scheme::spectral, a, 1.0, 8, 0.25).speed / c;
    EXPECT_NEAR(ratio, 1.0, 5e-3) << "a " << a;
    RecordProperty(fmt::format("spectral_error_a{}", a), fmt::format("{:.2e}", ratio - 1));
  }
}

}  // namespace
}  // namespace shockfield::phasefield
