// Diagnostics on analytic fields: rotation, divergence and strain rate of a linear velocity field
// from the nodal velocities; window means; stress quantities; cavity area, sizes and collapsibility;
// ejecta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <numbers>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/cavity_tracker.hpp"
#include "shockfield/mpm/diagnostics.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace {

using namespace shockfield;

// v = (a·y, c·y): L = [[0, a], [0, c]], so |∇×v|² = a², (∇·v)² = c², D:D = c² + a²/2. The MPM
// nodal velocities of a linear field on a uniform lattice are exact, and so is L_p inside the body.
TEST(MpmDiagnostics, GradientSquaresOfALinearField) {
  const auto al = materials::aluminium_seed000();
  const double h = 10e-6, a = 2e5, c = -3e5;
  mpm::Particles p;
  mpm::add_body(p, 2, {Vec3(0, 0, 0), Vec3(200e-6, 400e-6, 0), h / 2, Vec3::Zero(), 0}, al);
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = Vec3(a * p.x[i][1], c * p.x[i][1], 0);
  mpm::Simulation sim(mpm::impact_grid(2, Vec3(0, -50e-6, 0), Vec3(200e-6, 450e-6, 0), h), {al}, std::move(p));
  sim.step(1e-18);  // L_p from the nodal velocities; the motion itself is negligible
  const auto w = mpm::window_stats(sim.particles(), 2, 100e-6, 300e-6, 200e-6);
  EXPECT_EQ(w.count, 40u * 40u);  // spacing h/2
  EXPECT_NEAR(w.gradients[0], a * a, 1e-9 * a * a);
  EXPECT_NEAR(w.gradients[1], c * c, 1e-9 * c * c);
  EXPECT_NEAR(w.gradients[2], c * c + 0.5 * a * a, 1e-9 * c * c);
  const auto quantities = mpm::window_quantities(2);
  ASSERT_EQ(quantities[4].name, "vy");  // a velocity: v, never u (docs/conventions.md)
  ASSERT_EQ(quantities[4].unit, "m_s");
  EXPECT_NEAR(w.mean[4], c * 200e-6, 1e-9 * std::abs(c) * 200e-6);  // mean of c·y over y in [100, 300] µm
  EXPECT_NEAR(w.std[4], std::abs(c) * 200e-6 / std::sqrt(12.0), 0.01 * std::abs(c) * 200e-6 / std::sqrt(12.0));
  EXPECT_NEAR(w.mean[0], 2700.0, 1e-6);  // density unchanged
  EXPECT_NEAR(w.std[0], 0.0, 1e-6);
  EXPECT_NEAR(w.bulk_density, 2700.0, 1e-9);  // a full window: mass / area
  EXPECT_EQ(mpm::window_stats(sim.particles(), 2, 1.0, 2.0, 1.0).count, 0u);
}

TEST(MpmDiagnostics, GradientSquaresOfARotation) {
  Mat3 l = Mat3::Zero();
  l(0, 1) = -1.0, l(1, 0) = 1.0;  // rigid rotation ω = 1/s: curl 2ω, no divergence or strain rate
  const auto g = mpm::gradient_squares(l);
  EXPECT_DOUBLE_EQ(g[0], 4.0);
  EXPECT_DOUBLE_EQ(g[1], 0.0);
  EXPECT_DOUBLE_EQ(g[2], 0.0);
}

// A disc of radius 20 spacings: area within the raster's resolution, sizes 2r, Φ = 0; then the
// same body without the cavity (fully collapsed) gives A = 0, Φ = 1.
TEST(MpmDiagnostics, CavityAreaSizesAndCollapsibility) {
  const auto al = materials::aluminium_seed000();
  const double s = 1e-6, r = 20e-6;
  const mpm::Body body{Vec3(0, 0, 0), Vec3(100e-6, 100e-6, 0), s, Vec3(0, 50.0, 0), 0};
  const mpm::Void cavity = mpm::cavity_at(2, body, 50e-6, r);
  mpm::Particles p;
  mpm::add_body(p, 2, body, al, {cavity});
  mpm::CavityTracker tracker(2, cavity, s);
  const mpm::CavityMeasure m = tracker.measure(p, 0.0);
  const double area = std::numbers::pi * r * r;
  EXPECT_NEAR(m.size, area, 0.04 * area);
  EXPECT_NEAR(m.horizontal, 2 * r, 2 * s);
  EXPECT_NEAR(m.vertical, 2 * r, 2 * s);
  EXPECT_DOUBLE_EQ(m.collapsibility, 0.0);
  EXPECT_DOUBLE_EQ(m.v_up_above, 50.0);
  EXPECT_DOUBLE_EQ(m.v_down_below, 50.0);
  const auto state = tracker.state();

  mpm::Particles full;
  mpm::add_body(full, 2, body, al);
  mpm::CavityTracker resumed(2, cavity, s);
  resumed.restore(state);
  const mpm::CavityMeasure gone = resumed.measure(full, 0.0);
  EXPECT_EQ(gone.size, 0.0);
  EXPECT_DOUBLE_EQ(gone.collapsibility, 1.0);
}

TEST(MpmDiagnostics, EjectaAboveTheFreeSurface) {
  const auto al = materials::aluminium_seed000();
  const double h = 10e-6;
  mpm::Particles p;
  mpm::add_body(p, 2, {Vec3(0, 0, 0), Vec3(200e-6, 100e-6, 0), h / 2, Vec3::Zero(), 0}, al);
  mpm::Grid grid(mpm::impact_grid(2, Vec3(0, 0, 0), Vec3(200e-6, 300e-6, 0), h));
  EXPECT_EQ(mpm::ejecta(p, grid, 2 * h).count, 0.0);
  for (std::size_t i = 0; i < 3; ++i) p.x[i][1] = 150e-6;  // three points thrown 52.5 µm above the surface
  const mpm::Ejecta e = mpm::ejecta(p, grid, 2 * h);
  EXPECT_NEAR(e.surface, 97.5e-6, 1e-12);
  EXPECT_EQ(e.count, 3.0);
  EXPECT_DOUBLE_EQ(e.mass, 3 * p.mass[0]);
  EXPECT_NEAR(e.max_height, 52.5e-6, 1e-12);
}

// The stress quantities of the windows and histograms on a state set by hand: a point in uniaxial
// compression at yield along the shock axis, s = diag(Y/3, −2Y/3, Y/3) (2D: the shock axis is y),
// P = 2 GPa, q = 0.1 GPa. σ_yy = s_yy − P − q = −2.18 GPa, s_yy = −80 MPa, von Mises
// √(3/2)‖s‖ = Y = 120 MPa (eq. 3), pressure −tr σ/3 = P + q. In 3D the shock axis is z.
TEST(MpmDiagnostics, StressQuantitiesAlongTheShockAxis) {
  const auto cu = materials::copper();
  for (int dim : {2, 3}) {
    mpm::Particles p;
    p.add(Vec3::Zero(), Vec3::Zero(), 1e-12, Vec3::Constant(1e-6), cu, 0);
    const int axis = dim - 1;
    const double y = 120e6;
    Mat3 s = Mat3::Zero();
    for (int a = 0; a < 3; ++a) s(a, a) = a == axis ? -2.0 * y / 3.0 : y / 3.0;
    p.state[0].deviatoric.s = s;
    p.state[0].pressure = 2e9;
    p.state[0].viscous_pressure = 0.1e9;
    const auto quantities = mpm::window_quantities(dim);
    const auto at = [&](const std::string& n) {
      const auto it = std::find_if(quantities.begin(), quantities.end(), [&](const auto& q) { return q.name == n; });
      EXPECT_NE(it, quantities.end()) << n;
      return mpm::quantity(p, 0, static_cast<std::size_t>(it - quantities.begin()), dim);
    };
    EXPECT_EQ(quantities.size(), static_cast<std::size_t>(3 + dim + 3));
    EXPECT_EQ(quantities[static_cast<std::size_t>(2 + dim)].name, dim == 2 ? "vy" : "vz");  // velocities keep their columns
    EXPECT_NEAR(at("longitudinal_stress"), -2.1e9 - 2.0 * y / 3.0, 1.0);
    EXPECT_NEAR(at("longitudinal_deviator"), -2.0 * y / 3.0, 1e-6);
    EXPECT_NEAR(at("von_mises"), y, 1e-6);
    EXPECT_NEAR(at("pressure"), 2.1e9, 1.0);
  }
}

}  // namespace
