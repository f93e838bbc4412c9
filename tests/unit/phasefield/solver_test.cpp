// The solver's invariants: F non-increasing, explicit and spectral agreeing, thread-count
// independence, and the refusal of bad parameters.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <stdexcept>

#include "shockfield/phasefield/initial.hpp"
#include "shockfield/phasefield/solver.hpp"

namespace shockfield::phasefield {
namespace {

const Grid kGrid{2, {64, 48, 1}, 0.5};
const Model kModel{0.45, 1.0};

std::vector<double> nuclei(const Grid& g = kGrid) {
  return initial_field(g, kModel, random_domains(g, {12, 3.0, 7}));
}

// F of the gradient flow must not increase (dF/dt = −∫(∂ₜξ)² ≤ 0); the discrete F of the explicit
// scheme (forward differences) is its exact Lyapunov function for small dt. Checked every step
// with a round-off allowance of 1e-12 relative.
TEST(PhasefieldSolver, FreeEnergyNonIncreasing) {
  for (const Scheme scheme : {Scheme::explicit_euler, Scheme::spectral}) {
    Solver s(kGrid, kModel, scheme, 0.5 * explicit_step_limit(kGrid, kModel));
    s.field() = nuclei();
    double F = s.measures().free_energy;
    for (int k = 0; k < 400; ++k) {
      s.step();
      const double next = s.measures().free_energy;
      ASSERT_LE(next, F + 1e-12 * std::abs(F)) << scheme_name(scheme) << " step " << k;
      F = next;
    }
  }
}

// Same nuclei, same dt (0.4 of the explicit limit), t = 20: the schemes differ only by the
// O(dx²) error of the 5-point Laplacian and the O(dt) splitting; max |Δξ| < 5e-3 (measured 8.3e-4)
// and the hcp area within 0.5 %.
TEST(PhasefieldSolver, ExplicitAndSpectralAgree) {
  const Grid g{2, {128, 128, 1}, 0.25};
  const double dt = 0.4 * explicit_step_limit(g, kModel);
  Solver e(g, kModel, Scheme::explicit_euler, dt), f(g, kModel, Scheme::spectral, dt);
  e.field() = f.field() = initial_field(g, kModel, random_domains(g, {6, 3.0, 3}));
  while (e.time() < 20.0) e.step(), f.step();
  double diff = 0;
  for (std::size_t p = 0; p < g.size(); ++p) diff = std::max(diff, std::abs(e.field()[p] - f.field()[p]));
  EXPECT_LT(diff, 5e-3);
  EXPECT_NEAR(e.measures().integral / f.measures().integral, 1.0, 5e-3);
  RecordProperty("max_field_difference", std::to_string(diff));
}

std::vector<double> run_threads(Scheme scheme, int threads) {
  omp_set_num_threads(threads);
  const Grid g{3, {24, 20, 16}, 0.5};
  Solver s(g, kModel, scheme, 0.5 * explicit_step_limit(g, kModel));
  s.field() = nuclei(g);
  for (int k = 0; k < 30; ++k) s.step();
  std::vector<double> out = s.field();
  const FieldMeasures m = s.measures();
  out.insert(out.end(), {m.free_energy, m.integral, m.fraction_above_half});
  omp_set_num_threads(1);
  return out;
}

TEST(PhasefieldSolver, OneAndTwoThreadsBitwiseEqual) {
  for (const Scheme scheme : {Scheme::explicit_euler, Scheme::spectral})
    EXPECT_EQ(run_threads(scheme, 1), run_threads(scheme, 2)) << scheme_name(scheme);
}

TEST(PhasefieldSolver, RefusesBadParameters) {
  const double limit = explicit_step_limit(kGrid, kModel);
  EXPECT_THROW(Solver(kGrid, kModel, Scheme::explicit_euler, 1.01 * limit), std::invalid_argument);
  EXPECT_NO_THROW(Solver(kGrid, kModel, Scheme::spectral, 10 * limit));
  EXPECT_THROW(Solver(kGrid, Model{0.4, -1.0}, Scheme::spectral, 0.1), std::invalid_argument);
  EXPECT_THROW(Solver(kGrid, Model{0.4, NAN}, Scheme::spectral, 0.1), std::invalid_argument);
  EXPECT_THROW(Solver(kGrid, kModel, Scheme::spectral, NAN), std::invalid_argument);
  EXPECT_THROW(scheme_from_name("implicit"), std::invalid_argument);
}

// A zero-flux wall is a mirror: a field symmetric about x = 0 on a periodic grid of 2(n − 1)
// nodes equals, node for node and bitwise, the same field on n nodes between neumann walls (the
// ghost ξ₋₁ = ξ₁ is the periodic neighbour's value). A disc centred on the wall, growing (a = 0.4).
TEST(PhasefieldSolver, NeumannWallIsAMirror) {
  const int n = 33;
  Grid periodic{2, {2 * (n - 1), 48, 1}, 0.5};
  Grid walls = periodic;
  walls.n[0] = n;
  walls.boundary[0] = Boundary::neumann;
  const Model model{0.4, 1.0};
  // Radius 9 above the critical D/c₀ = 7.07: the disc grows.
  const std::vector<Domain> disc{{Domain::Kind::sphere, {0.0, 12.0, 0.0}, {9.0, 9.0, 9.0}}};
  Solver a(periodic, model, Scheme::explicit_euler, 0.05), b(walls, model, Scheme::explicit_euler, 0.05);
  a.field() = initial_field(periodic, model, disc);
  b.field() = initial_field(walls, model, disc);
  for (int s = 0; s < 400; ++s) a.step(), b.step();
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < n; ++i) ASSERT_EQ(a.field()[periodic.index(i, j, 0)], b.field()[walls.index(i, j, 0)]) << i << " " << j;
  EXPECT_GT(b.measures().integral, 0.5 * std::acos(-1.0) * 81.0);  // the half disc grew
  // Trapezoidal measures: half the periodic hcp volume (the walls' nodes count half a cell).
  EXPECT_NEAR(b.measures().integral, 0.5 * a.measures().integral, 1e-12 * a.measures().integral);
}

// A gradient coefficient varying in space (the pressure-dependent D): a uniform scale s is the
// model with D s (to round-off: the face mean of two equal scales is exact, the order of products
// differs); with a scale varying between 0.5 and 2 the discrete free energy still never increases
// (the face-averaged flux is the gradient flow of F = Σ [f + D s_face/2 |∇ξ|²]); refusals.
TEST(PhasefieldSolver, DiffusivityVaryingInSpace) {
  const Model scaled{kModel.a, 1.7 * kModel.D};
  const double dt = 0.5 * explicit_step_limit(kGrid, scaled);
  Solver a(kGrid, kModel, Scheme::explicit_euler, dt), b(kGrid, scaled, Scheme::explicit_euler, dt);
  a.set_diffusivity_scale(std::vector<double>(kGrid.size(), 1.7));
  a.field() = b.field() = nuclei();
  for (int k = 0; k < 100; ++k) a.step(), b.step();
  for (std::size_t p = 0; p < kGrid.size(); ++p) ASSERT_NEAR(a.field()[p], b.field()[p], 1e-13) << p;

  std::vector<double> scale(kGrid.size());
  for (std::size_t p = 0; p < scale.size(); ++p) scale[p] = 1.25 + 0.75 * std::sin(0.37 * static_cast<double>(p));
  Solver c(kGrid, kModel, Scheme::explicit_euler, 0.4 * explicit_step_limit(kGrid, kModel) / 2.0);
  c.set_diffusivity_scale(scale);
  c.field() = nuclei();
  double previous = c.measures().free_energy;
  for (int k = 0; k < 300; ++k) {
    c.step();
    const double now = c.measures().free_energy;
    ASSERT_LE(now, previous + 1e-12 * std::abs(previous)) << "step " << k;
    previous = now;
  }
  Solver d(kGrid, kModel, Scheme::explicit_euler, 0.9 * explicit_step_limit(kGrid, kModel));
  EXPECT_THROW(d.set_diffusivity_scale(scale), std::invalid_argument);  // max s = 2: dt beyond the limit
  EXPECT_THROW(d.set_diffusivity_scale(std::vector<double>(kGrid.size(), -1.0)), std::invalid_argument);
  EXPECT_THROW(d.set_diffusivity_scale(std::vector<double>(3, 1.0)), std::invalid_argument);
  Solver e(kGrid, kModel, Scheme::spectral, 0.1);
  EXPECT_THROW(e.set_diffusivity_scale(std::vector<double>(kGrid.size(), 1.0)), std::invalid_argument);
}

// Dirichlet walls hold their values; the spectral scheme refuses walls.
TEST(PhasefieldSolver, DirichletWallsHoldTheirValues) {
  Grid g{1, {40, 1, 1}, 0.5};
  g.boundary[0] = Boundary::dirichlet;
  g.fixed[0] = {1.0, 0.0};
  EXPECT_THROW(Solver(g, kModel, Scheme::spectral, 0.05), std::invalid_argument);
  Solver s(g, Model{0.5, 1.0}, Scheme::explicit_euler, 0.05);
  for (int k = 0; k < 4000; ++k) s.step();
  EXPECT_EQ(s.field().front(), 1.0);
  EXPECT_EQ(s.field().back(), 0.0);
  // The hcp wall's phase entered (a = 1/2: no bulk drive) and the profile falls monotonically.
  EXPECT_GT(s.field()[5], 0.5);
  for (int i = 1; i < 40; ++i) EXPECT_LE(s.field()[i], s.field()[i - 1]) << i;
}

// A 3D sphere of radius 6 = 4.2 l: ξ = 1/2 at its surface on the axis, the tanh profile across it.
TEST(PhasefieldInitial, SphereHasTanhProfile) {
  const Grid g{3, {32, 32, 32}, 0.5};
  const auto xi = initial_field(g, kModel, {Domain{Domain::Kind::sphere, {8, 8, 8}, {6, 6, 6}}});
  for (int i = 16; i < 32; ++i) EXPECT_NEAR(xi[g.index(i, 16, 16)], kModel.profile(i * 0.5 - 8 - 6), 1e-14);
  // Ellipsoid semi-axes 6, 3, 2: the half level on each axis.
  const auto e = initial_field(g, kModel, {Domain{Domain::Kind::ellipsoid, {8, 8, 8}, {6, 3, 2}}});
  EXPECT_NEAR(e[g.index(28, 16, 16)], 0.5, 1e-14);
  EXPECT_NEAR(e[g.index(16, 22, 16)], 0.5, 1e-14);
  EXPECT_NEAR(e[g.index(16, 16, 20)], 0.5, 1e-14);
}

}  // namespace
}  // namespace shockfield::phasefield
