// The 1D travelling front of ∂ₜξ = −f′(ξ) + D∇²ξ against its closed form (Nagumo wave,
// docs/theory/phasefield.md): speed c₀ = √(D/2)(1 − 2a) and profile [1 − tanh(d/(2√(2D)))]/2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
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
// `dim`, `axis`: the same line as the `axis` of a grid of `dim` dimensions, 3 nodes across.
FrontRun run_front(Scheme scheme, double a, double D, int nodes_per_length, double dt_factor, int dim = 1,
                   int axis = 0, std::array<double, 3> anisotropy = {1, 1, 1}) {
  Model model{a, D};
  model.anisotropy = anisotropy;
  const double l = model.front_length();
  Grid grid{dim, {1, 1, 1}, l / nodes_per_length};
  for (int d = 0; d < dim; ++d) grid.n[d] = d == axis ? 80 * nodes_per_length : 3;
  double cross_section = 1;  // the front's area
  for (int d = 0; d < dim; ++d)
    if (d != axis) cross_section *= grid.length(d);
  const double dt = dt_factor * explicit_step_limit(grid, model);
  Solver solver(grid, model, scheme, dt);
  const double half = 20 * l, center = 40 * l;
  Domain slab{Domain::Kind::slab, {0, 0, 0}, {half, 0, 0}, {0, 0, 0}};
  slab.center[axis] = center;
  slab.normal[axis] = 1;
  solver.field() = initial_field(grid, model, {slab});
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
  const double slope = (count * sty - st * sy) / (count * stt - st * st) / cross_section;
  // The right front: the ξ = 1/2 crossing by linear interpolation, then the profile about it.
  const int n = grid.n[axis];
  std::vector<double> xi(n);
  for (int i = 0; i < n; ++i) xi[i] = solver.field()[grid.index(axis == 0 ? i : 0, axis == 1 ? i : 0, axis == 2 ? i : 0)];
  double front = 0;
  for (int i = n / 2; i + 1 < n; ++i)
    if (xi[i] >= 0.5 && xi[i + 1] < 0.5) {
      front = (i + (xi[i] - 0.5) / (xi[i] - xi[i + 1])) * grid.dx;
      break;
    }
  double err = 0;
  for (int i = n / 2; i < n; ++i) err = std::max(err, std::abs(xi[i] - model.profile(i * grid.dx - front)));
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

// The same fronts along x, y and z of a 3D grid (3 nodes across), both schemes, l/dx = 8: the
// stencil and the FFT along every axis. l/dx = 4 (to keep the test short); explicit at 0.5 of its
// 3D limit, spectral at dx²/(8D); within 0.5 % of c₀ (measured in the properties).
TEST(PhasefieldFront, SpeedAlongEachAxisIn3D) {
  const double a = 0.3, c = Model{a, 1.0}.front_speed();
  for (int axis = 0; axis < 3; ++axis) {
    const double e = run_front(Scheme::explicit_euler, a, 1.0, 4, 0.5, 3, axis).speed / c - 1;
    const double f = run_front(Scheme::spectral, a, 1.0, 4, 0.75, 3, axis).speed / c - 1;
    EXPECT_LT(std::abs(e), 5e-3) << "axis " << axis;
    EXPECT_LT(std::abs(f), 5e-3) << "axis " << axis;
    RecordProperty(fmt::format("explicit_error_axis{}", axis), fmt::format("{:.2e}", e));
    RecordProperty(fmt::format("spectral_error_axis{}", axis), fmt::format("{:.2e}", f));
  }
}

// Anisotropic gradient energy: D_d = D w_d. A front normal to axis d moves at √(D w_d/2)(1 − 2a),
// √w_d times the isotropic speed: along x (w = 9/4) 1.5 times, along y (w = 1/4) half; explicit
// (the stability limit dx²/(2 Σ D_d) set by the stiff axis) and spectral, within 0.5 %. (At w = 4
// the fronts, moving 16 l in the run, come within 4 front lengths of their periodic images, which
// slows them by 2.4 %.)
TEST(PhasefieldFront, AnisotropicSpeedScalesWithTheRootOfD) {
  const double a = 0.3, c = Model{a, 1.0}.front_speed();
  const std::array<double, 3> w{2.25, 0.25, 1.0};
  for (int axis = 0; axis < 2; ++axis) {
    const double expected = std::sqrt(w[axis]) * c;
    const double e = run_front(Scheme::explicit_euler, a, 1.0, 8, 0.5, 3, axis, w).speed / expected - 1;
    const double f = run_front(Scheme::spectral, a, 1.0, 8, 0.75, 3, axis, w).speed / expected - 1;
    EXPECT_LT(std::abs(e), 5e-3) << "axis " << axis;
    EXPECT_LT(std::abs(f), 5e-3) << "axis " << axis;
    RecordProperty(fmt::format("anisotropic_explicit_error_axis{}", axis), fmt::format("{:.2e}", e));
    RecordProperty(fmt::format("anisotropic_spectral_error_axis{}", axis), fmt::format("{:.2e}", f));
  }
}

}  // namespace
}  // namespace shockfield::phasefield
