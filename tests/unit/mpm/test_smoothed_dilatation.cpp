// The smoothed dilatation (`smooth_dilatation`) with its B-bar grid force (docs/theory/mpm.md,
// "B-bar"): the internal force must be minus the derivative of the stored energy with respect to
// the nodal displacements, the finite-difference check of DESIGN.md, and an elastic run must
// conserve energy as well as without the option.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <cmath>
#include <vector>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/diagnostics.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/simulation.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

/// Elastic (yield far above the stresses reached), no artificial viscosity: the stored energy is
/// the work of the stress alone.
materials::SolidMaterial elastic() {
  auto m = materials::elastic_plastic("elastic", 2703.0, 77.11e9, 0.334, 1e12);
  m.viscosity.linear = 0.0;
  m.viscosity.quadratic = 0.0;
  return m;
}

/// A block of 3^dim cells, 2 points per cell and axis, at rest, each point brought to its own
/// elastic state (a different compression and shear per point, up to ~1 GPa) by one material
/// update, so the pressure is far from uniform: the case where the smoothed and the plain
/// dilatation disagree.
mpm::Simulation prestressed_block(int dim, bool smooth) {
  const double h = 1e-3;
  const auto mat = elastic();
  mpm::Particles p;
  const int per_axis = 6;
  const double spacing = h / 2, volume = std::pow(spacing, dim);
  int k = 0;
  for (int c = 0; c < (dim == 3 ? per_axis : 1); ++c)
    for (int b = 0; b < per_axis; ++b)
      for (int a = 0; a < per_axis; ++a, ++k) {
        const Vec3 x((a + 0.5) * spacing, (b + 0.5) * spacing, dim == 3 ? (c + 0.5) * spacing : 0.0);
        p.add(x + Vec3::Constant(2 * h), Vec3::Zero(), volume, Vec3::Constant(spacing / 2), mat, 0);
        Mat3 l = Mat3::Zero();  // a fixed pseudo-random strain per point, a few 10⁻³
        for (int r = 0; r < dim; ++r)
          for (int s = 0; s < dim; ++s) l(r, s) = 4e-3 * std::sin(1.7 * k + 2.3 * r + 0.9 * s) - (r == s ? 3e-3 : 0.0);
        auto& st = p.state.back();
        mat.update(st, mat.eos.rho0, l, 1.0, h, dim == 2);
      }
  mpm::GridSpec g;
  g.dim = dim;
  g.cell_size = Vec3::Constant(h);
  g.cells = {7, 7, dim == 3 ? 7 : 1};
  mpm::SimulationOptions o;
  o.shape = mpm::ShapeKind::Gimp;
  o.scheme = mpm::UpdateScheme::USL;  // L_p from the nodal velocities the hook sets (no remap)
  o.smooth_dilatation = smooth;
  return mpm::Simulation(g, {mat}, std::move(p), o);
}

struct Probe {
  std::vector<Vec3> force;  // f_i of the step (the particles are at rest: f_i = Δ(m v)_i / Δt)
  std::vector<double> mass;  // m_i
  double stored = 0.0;      // Σ_p m_p Δe_p over the step
};

/// One step of `dt` in which node `node` moves at `speed` along `axis` and every other node is
/// held: the stored-energy increment Σ_p m_p Δe_p and the internal force of the step.
Probe one_step(int dim, bool smooth, std::size_t node, int axis, double speed, double dt) {
  auto sim = prestressed_block(dim, smooth);
  const std::vector<materials::PointState> before = sim.particles().state;
  Probe out;
  sim.add_hook(mpm::Stage::AfterGridUpdate, [&](mpm::Simulation& run) {
    auto& grid = run.grid();
    out.force = grid.force;
    out.mass = grid.mass;
    for (auto& m : grid.momentum) m.setZero();
    grid.momentum[node][axis] = grid.mass[node] * speed;
  });
  sim.step(dt);
  const auto& p = sim.particles();
  for (std::size_t q = 0; q < p.size(); ++q) out.stored += p.mass[q] * (p.state[q].energy - before[q].energy);
  return out;
}

void expect_force_is_energy_gradient(int dim) {
  // Nodal displacement 1e-10 m = 1e-7 h: the O(ε²) terms cancel in the central difference and
  // what is left is round-off (the error grows as 1/displacement: 2.5e-9 / 1.7e-8 / 2.0e-7 of the
  // largest force in 2D at 1e-10 / 1e-11 / 1e-12 m).
  const double dt = 1e-9, speed = 1e-1;
  const Probe at_rest = one_step(dim, true, 0, 0, 0.0, dt);
  const Probe plain = one_step(dim, false, 0, 0, 0.0, dt);
  const double mass = prestressed_block(dim, true).particles().mass[0];
  double scale = 0.0, worst = 0.0, worst_plain = 0.0;
  for (const Vec3& f : at_rest.force) scale = std::max(scale, f.cwiseAbs().maxCoeff());
  int checked = 0;
  for (std::size_t i = 0; i < at_rest.force.size(); ++i) {
    // Nodes a GIMP box just reaches carry no velocity below the mass floor (1e-9 of a point's mass,
    // simulation.cpp): the energy does not see them move although a force acts there.
    if (at_rest.mass[i] < 1e-6 * mass) continue;
    for (int a = 0; a < dim; ++a) {
      const double up = one_step(dim, true, i, a, speed, dt).stored, down = one_step(dim, true, i, a, -speed, dt).stored;
      const double minus_gradient = -(up - down) / (2 * speed * dt);  // −∂W/∂u_ia
      worst = std::max(worst, std::abs(at_rest.force[i][a] - minus_gradient));
      worst_plain = std::max(worst_plain, std::abs(plain.force[i][a] - minus_gradient));
      ++checked;
    }
  }
  EXPECT_GT(checked, 8 * dim);
  // The B-bar force is the energy gradient to round-off (1e-6 of the largest nodal force;
  // measured 2.5e-9 in 2D, 7.9e-9 in 3D). The plain force −Σ_p V_p σ_p·∇N_ip is not: with a
  // pressure varying by ~1 GPa from point to point it misses the gradient by a good part of the
  // force (measured 0.0084 of the largest in 2D, 0.058 in 3D; the bound is 1e-3), so this check can fail.
  EXPECT_LT(worst, 1e-6 * scale);
  EXPECT_GT(worst_plain, 1e-3 * scale);
  ::testing::Test::RecordProperty("relative_error_bbar", fmt::format("{:.3g}", worst / scale));
  ::testing::Test::RecordProperty("relative_error_plain_force", fmt::format("{:.3g}", worst_plain / scale));
}

}  // namespace

TEST(SmoothedDilatation, GridForceIsMinusStoredEnergyGradient2D) { expect_force_is_energy_gradient(2); }
TEST(SmoothedDilatation, GridForceIsMinusStoredEnergyGradient3D) { expect_force_is_energy_gradient(3); }

namespace {

/// Two porous elastic bodies (10 % voids of 40 µm, 15 cells of 20 µm per body) in symmetric impact
/// at ±100 m/s, 2D, run for two transits of the elastic wave: the voids make the pressure strongly
/// non-uniform, the case where a smoothed dilatation that is not work-conjugate with the grid force
/// gains or loses energy. Returns the total-energy drift (kinetic + internal) relative to the
/// initial kinetic energy.
double porous_elastic_energy_drift(bool smooth, bool shock_capturing) {
  auto mat = elastic();
  if (shock_capturing) mat.viscosity = materials::ArtificialViscosity{};  // the defaults; their heat is in e
  const double h = 20e-6, width = 0.4e-3, height = 0.3e-3, speed = 100.0;
  mpm::VoidSpec voids;
  voids.porosity = 0.1;
  voids.mean_radius = 40e-6;
  voids.seed = 3;
  const mpm::PeriodicAxes periodic{true, false, false};
  mpm::Particles p;
  for (const double side : {-1.0, 1.0}) {
    const mpm::Body body{Vec3(0, side < 0 ? -height : 0.0, 0), Vec3(width, side < 0 ? 0.0 : height, 0), h / 2,
                         Vec3(0, -side * speed, 0), 0};
    mpm::add_body(p, 2, body, mat, mpm::place_voids(2, body, voids, periodic));
  }
  auto o = mpm::SimulationOptions{};
  o.shape = mpm::ShapeKind::Gimp;
  o.smooth_dilatation = smooth;
  const auto grid = mpm::impact_grid(2, Vec3(0, -height - 10 * h, 0), Vec3(width, height + 10 * h, 0), h);
  mpm::Simulation sim(grid, {mat}, std::move(p), o);
  const mpm::Totals t0 = mpm::totals(sim.particles());
  sim.run_until(2 * height / 6550.0);
  return (mpm::totals(sim.particles()).total() - t0.total()) / t0.kinetic;
}

}  // namespace

// The option costs no energy beyond the MPM's own drift without it. Measured (drift, % of the
// initial kinetic energy; without / with the smoothing; with the former force −Σ_p V_p σ_p·∇N_ip):
// no artificial viscosity −5.58 / −5.56 (former −5.96); default C_L = 1, C_Q = 2: −4.55 / −4.78
// (former −6.00). The drift without the option is first order in h (−5.6 / −2.8 / −1.4 % at 20 /
// 10 / 5 µm, no viscosity), and the smoothed run follows it (−5.56 / −2.85 / −1.42 %). Bounds:
// 0.1 and 0.5 percentage points from the drift without the option (the former force misses them
// by 0.38 and 1.46 points, so the check fails without the B-bar force).
TEST(SmoothedDilatation, PorousElasticImpactConservesEnergyAsWithoutTheOption) {
  for (const bool shock_capturing : {false, true}) {
    const double plain = porous_elastic_energy_drift(false, shock_capturing);
    const double smoothed = porous_elastic_energy_drift(true, shock_capturing);
    EXPECT_NEAR(smoothed, plain, shock_capturing ? 0.005 : 0.001) << "artificial viscosity " << shock_capturing;
    EXPECT_LT(std::abs(plain), 0.07);  // the bound the option-off run is held to here (measured 5.6 %)
    EXPECT_LT(std::abs(smoothed), 0.07);
    const std::string k = shock_capturing ? "_viscosity" : "_no_viscosity";
    ::testing::Test::RecordProperty("drift_plain" + k, fmt::format("{:.4g}", plain));
    ::testing::Test::RecordProperty("drift_smoothed" + k, fmt::format("{:.4g}", smoothed));
  }
}
