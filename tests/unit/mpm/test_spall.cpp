// Spall (materials/spall.hpp) in a 1D flyer-plate impact: a flyer of thickness d hits a target of
// thickness 3d of the same material at v. The releases from the flyer's back and the target's free
// face meet a distance d below the free face and put it in tension. With a spall strength σ_sp
// below that tension the target fails there, and the free-surface velocity, after its plateau at
// v (symmetric impact: u_fs = 2u_p = v), is pulled back only by Δu_fs before the spall signal
// turns it up again. Acoustic approximation (Antoun et al., Spall Fracture, 2003, §2.2):
// σ_sp ≈ ½·ρ0·c0·Δu_fs. Without the model the pull-back is the full v (the free face comes to
// rest).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/particles.hpp"
#include "strip.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

constexpr double kCell = 1e-4, kSpeed = 200.0;
constexpr int kFlyerCells = 40;

// The paper's aluminium made hydrodynamic (σ_Y0 = 1 kPa, no hardening): the pull-back then travels
// at the bulk sound speed c0 that the acoustic formula uses (no elastic precursor to correct for).
materials::SolidMaterial hydrodynamic_al(double spall_strength) {
  auto m = materials::aluminium_seed000();
  m.strength.yield_stress0 = 1e3;
  m.strength.tangent_modulus = 0.0;
  m.spall.strength = spall_strength;
  // The pull-back windows below were measured with C_L = 0.3, the default until the deviator fix
  // (docs/theory/mpm.md, "Deviatoric stress behind shocks"); with today's C_L = 1 the linear term
  // fills the notch differently in the two codes (at σ_sp = 1 GPa the 1D reference reads 0.73·σ_sp,
  // the MPM 0.57·σ_sp), which is not what this test is about.
  m.viscosity.linear = 0.3;
  m.validate();
  return m;
}

struct FreeSurface {
  std::vector<double> t, u;  // time [s], mean v_y of the top particle row [m/s]
  double peak = 0.0, pullback = 0.0, max_damage = 0.0, energy_drift = 0.0;
};

// Mean velocity along `axis` of the particles within a quarter cell of the highest one (the free
// face's row).
double top_row_velocity(const mpm::Particles& p, int axis) {
  double top = -INFINITY, sum = 0.0;
  int n = 0;
  for (const Vec3& x : p.x) top = std::max(top, x[axis]);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i][axis] > top - 0.25 * kCell) sum += p.v[i][axis], ++n;
  return sum / n;
}

// Plateau: the median of u_fs over the 0.5 µs after it first reaches 95 % of v (it rings by a few
// %). Pull-back: from the plateau to the first minimum after u_fs falls 5 % of v below it.
void read_pullback(FreeSurface& fs) {
  std::size_t k = 0;
  while (fs.u[k] < 0.95 * kSpeed) ++k;
  std::vector<double> plateau;
  for (std::size_t i = k; i < fs.u.size() && fs.t[i] < fs.t[k] + 0.5e-6; ++i) plateau.push_back(fs.u[i]);
  std::nth_element(plateau.begin(), plateau.begin() + static_cast<long>(plateau.size() / 2), plateau.end());
  fs.peak = plateau[plateau.size() / 2];
  std::size_t m = k;
  while (m + 1 < fs.u.size() && fs.u[m] > fs.peak - 0.05 * kSpeed) ++m;
  while (m + 1 < fs.u.size() && fs.u[m + 1] <= fs.u[m]) ++m;
  fs.pullback = fs.peak - fs.u[m];
}

// Flyer d = kFlyerCells cells, target 3d, free surface at y = 3d; end after the spall signal.
double end_time(const materials::SolidMaterial& mat) {
  return 7.0 * kFlyerCells * kCell / mat.eos.c0;  // arrival 3d/Us, release 5d/c, spall signal ~7d/c
}

// In 2D the plates are 2 cells wide (periodic) and move along y; in 3D 2 × 2 cells, along z.
FreeSurface flyer_plate(const materials::SolidMaterial& mat, int dim = 2) {
  const double d = kFlyerCells * kCell;
  const int axis = dim - 1;
  Vec3 lateral = Vec3::Zero();
  for (int a = 0; a < axis; ++a) lateral[a] = 2 * kCell;
  mpm::Particles p;
  mpm::add_body(p, dim, {strip::along(axis, -d), lateral, kCell / 2, strip::along(axis, kSpeed), 0}, mat);
  mpm::add_body(p, dim, {Vec3::Zero(), lateral + strip::along(axis, 3 * d), kCell / 2, Vec3::Zero(), 0}, mat);
  const auto grid = mpm::impact_grid(dim, strip::along(axis, -d - 10 * kCell),
                                     lateral + strip::along(axis, 3 * d + 20 * kCell), kCell);
  mpm::SimulationOptions opt;
  opt.shape = mpm::ShapeKind::Gimp;
  mpm::Simulation sim(grid, {mat}, std::move(p), opt);
  const double e0 = mpm::totals(sim.particles()).total();
  FreeSurface fs;
  while (sim.time() < end_time(mat)) {
    sim.step();
    fs.t.push_back(sim.time());
    fs.u.push_back(top_row_velocity(sim.particles(), axis));
  }
  read_pullback(fs);
  for (const auto& s : sim.particles().state) fs.max_damage = std::max(fs.max_damage, s.damage);
  fs.energy_drift = (mpm::totals(sim.particles()).total() - e0) / e0;
  return fs;
}

// The same impact in a 1D Lagrangian hydrocode, the classical staggered scheme of von Neumann &
// Richtmyer (Wilkins, "Computer Simulation of Dynamic Phenomena", 1999, ch. 2): node velocities,
// one material point per cell advanced by the same SolidMaterial::update as the MPM points (EOS,
// artificial viscosity with ℓ = the cell size, energy, spall criterion), the same cell size and
// Courant number. The free-surface velocity is the last node's. It separates what the MPM adds to
// the pull-back (transfers, GIMP, particle sampling of the free face) from what any hydrocode with
// this material update reads at this resolution.
FreeSurface lagrangian_flyer_plate(const materials::SolidMaterial& mat) {
  const int n = 4 * kFlyerCells;  // flyer + target, one mesh (the MPM bodies share one grid too)
  std::vector<double> y(n + 1), u(n + 1, 0.0), node_mass(n + 1, 0.0);
  std::vector<materials::PointState> cell(n, mat.initial_state());
  for (int i = 0; i <= n; ++i) {
    y[i] = (i - kFlyerCells) * kCell;
    u[i] = i < kFlyerCells ? kSpeed : (i == kFlyerCells ? 0.5 * kSpeed : 0.0);
    node_mass[i] = mat.eos.rho0 * kCell * ((i > 0) + (i < n)) / 2.0;
  }
  const double courant = mpm::SimulationOptions{}.courant;
  FreeSurface fs;
  double time = 0.0;
  while (time < end_time(mat)) {
    double fastest = 0.0;
    for (int i = 0; i < n; ++i) fastest = std::max(fastest, cell[i].sound_speed + std::abs(u[i]));
    const double dt = courant * kCell / fastest;
    for (int i = 0; i <= n; ++i) {  // node force σ_yy(cell i) − σ_yy(cell i−1); σ = 0 outside
      const double above = i < n ? cell[i].stress()(1, 1) : 0.0;
      const double below = i > 0 ? cell[i - 1].stress()(1, 1) : 0.0;
      u[i] += dt * (above - below) / node_mass[i];
    }
    for (int i = 0; i < n; ++i) {  // L over the cell's length at the start of the step: F stays exact
      Mat3 l = Mat3::Zero();
      l(1, 1) = (u[i + 1] - u[i]) / (y[i + 1] - y[i]);
      mat.update(cell[i], mat.eos.rho0, l, dt, kCell);
    }
    for (int i = 0; i <= n; ++i) y[i] += dt * u[i];
    time += dt;
    fs.t.push_back(time);
    fs.u.push_back(u[n]);
  }
  read_pullback(fs);
  for (const auto& s : cell) fs.max_damage = std::max(fs.max_damage, s.damage);
  return fs;
}

}  // namespace

// σ_sp = 0.5 and 1 GPa, both below the ≈ 1.5 GPa tension the 200 m/s impact can reach. In the
// continuum the acoustic estimate is exact here (the tension branch of eq. 6 is linear, so the
// Riemann invariant σ + ρ0c0·u carries the spall-plane state to the free face unchanged), but at
// 0.1 mm cells every hydrocode with this material update reads it low: the pull-back is a notch of
// a few tens of ns that the artificial viscosity (acting on the spall signal, a compression wave)
// and the failure of several cells at once fill in on the way to the face. The 1D Lagrangian
// reference below reads 0.61 and 0.64·σ_sp; the independent examples/mpm_spall/hydrocode_1d.py
// (its own EOS; --shear 25.94e9 for the c_L in q) 0.60 and 0.60·σ_sp at 0.1 mm, and 0.98 and
// 0.97·σ_sp at 2.5 µm once these two are removed (examples/mpm_spall/README.md, "Against the
// spall relation"). So the test pins the understood
// value: the reference within [0.55, 0.70]·σ_sp, the MPM within 15 % of the reference and within
// [0.53, 0.73]·σ_sp (measured 0.56 and 0.66), and the estimate rising with σ_sp.
TEST(Spall, FreeSurfacePullbackMeasuresTheSpallStrength) {
  double estimate[2] = {0.0, 0.0};
  const double strengths[2] = {0.5e9, 1.0e9};
  for (int i = 0; i < 2; ++i) {
    const auto al = hydrodynamic_al(strengths[i]);
    const FreeSurface fs = flyer_plate(al), ref = lagrangian_flyer_plate(al);
    EXPECT_NEAR(fs.peak, kSpeed, 0.03 * kSpeed);
    EXPECT_NEAR(ref.peak, kSpeed, 0.03 * kSpeed);
    estimate[i] = 0.5 * al.eos.rho0 * al.eos.c0 * fs.pullback;
    const double reference = 0.5 * al.eos.rho0 * al.eos.c0 * ref.pullback;
    EXPECT_GT(reference, 0.55 * strengths[i]);
    EXPECT_LT(reference, 0.70 * strengths[i]);
    EXPECT_NEAR(estimate[i] / reference, 1.0, 0.15);
    EXPECT_GT(estimate[i], 0.53 * strengths[i]);
    EXPECT_LT(estimate[i], 0.73 * strengths[i]);
    EXPECT_EQ(fs.max_damage, 1.0);
    EXPECT_EQ(ref.max_damage, 1.0);
    EXPECT_LT(std::abs(fs.energy_drift), 0.01);
    RecordProperty("sigma_est_" + std::to_string(i), std::to_string(estimate[i]));
    RecordProperty("sigma_ref_" + std::to_string(i), std::to_string(reference));
    RecordProperty("energy_drift_" + std::to_string(i), std::to_string(fs.energy_drift));
  }
  const double rise = estimate[1] - estimate[0], expected = strengths[1] - strengths[0];
  EXPECT_GT(rise, 0.6 * expected);
  EXPECT_LT(rise, 1.1 * expected);
}

// The same impact without the model: the target carries the full tension (≈ the impact stress
// ½ρ0·c0·v ≈ 1.5 GPa), nothing fails, and the free face is pulled back to rest (Δu_fs = v).
TEST(Spall, WithoutTheModelThePullbackIsComplete) {
  const FreeSurface fs = flyer_plate(hydrodynamic_al(0.0));
  EXPECT_NEAR(fs.peak, kSpeed, 0.03 * kSpeed);
  EXPECT_NEAR(fs.pullback, kSpeed, 0.10 * kSpeed);
  EXPECT_EQ(fs.max_damage, 0.0);
  RecordProperty("pullback", std::to_string(fs.pullback));
}

// Tuler–Butcher damage (materials/spall.hpp) with the threshold σ_0 = 0.5 GPa of the first case
// above, λ = 2 and K_f = (0.5 GPa)²·20 ns: a point must stay in tension beyond σ_0 for a while before
// it fails, so the spall plane carries more tension than σ_0 and the pull-back grows with K_f (the
// law's rate effect), in the MPM and in the 1D Lagrangian reference with the same update alike.
// Measured ½ρ0c0Δu_fs: instantaneous 0.280 GPa; K_f = 5·10⁹ / 2·10¹⁰ Pa²·s: MPM 0.515 / 0.700 GPa,
// 1D reference 0.542 / 0.789 GPa (ratios 0.95 / 0.89); energy drift −0.8 %.
TEST(Spall, TulerButcherRaisesThePullback) {
  const auto instantaneous = hydrodynamic_al(0.5e9);
  double previous = 0.5 * instantaneous.eos.rho0 * instantaneous.eos.c0 * flyer_plate(instantaneous).pullback;
  for (double k_f : {0.25e18 * 20e-9, 0.25e18 * 80e-9}) {
    auto al = instantaneous;
    al.spall.tuler_butcher_exponent = 2.0;
    al.spall.tuler_butcher_integral = k_f;
    const FreeSurface fs = flyer_plate(al), ref = lagrangian_flyer_plate(al);
    const double estimate = 0.5 * al.eos.rho0 * al.eos.c0 * fs.pullback;
    const double reference = 0.5 * al.eos.rho0 * al.eos.c0 * ref.pullback;
    EXPECT_NEAR(estimate / reference, 1.0, 0.15) << k_f;  // the bound of the instantaneous case
    EXPECT_GT(estimate, 1.2 * previous) << k_f;
    EXPECT_EQ(fs.max_damage, 1.0);
    EXPECT_LT(std::abs(fs.energy_drift), 0.01);
    RecordProperty("sigma_est_Kf" + std::to_string(static_cast<int>(k_f / 1e9)), std::to_string(estimate));
    RecordProperty("sigma_ref_Kf" + std::to_string(static_cast<int>(k_f / 1e9)), std::to_string(reference));
    previous = estimate;
  }
}

// The flyer-plate impact of the first test (σ_sp = 1 GPa) in 3D: nothing varies across the plates,
// so the 3D run must give the 2D run's free-surface history — the same plateau, pull-back, failure
// and energy. Bound 1e-7 of v: the two differ only in summation order (see test_impact_3d.cpp),
// amplified over the ~2000 steps and the failures (measured 1e-9 of v on the plateau, 5e-9 on the
// pull-back); a 3D spall criterion or update that differed from 2D would move the pull-back by the
// ≥ 10 m/s that separate the cases of the tests above.
TEST(Spall, ThreeDimensionalFlyerPlateEqualsTwoDimensional) {
  const auto al = hydrodynamic_al(1.0e9);
  const FreeSurface two = flyer_plate(al, 2), three = flyer_plate(al, 3);
  EXPECT_NEAR(three.peak, two.peak, 1e-7 * kSpeed);
  EXPECT_NEAR(three.pullback, two.pullback, 1e-7 * kSpeed);
  EXPECT_EQ(three.max_damage, 1.0);
  EXPECT_LT(std::abs(three.energy_drift), 0.01);
  RecordProperty("pullback_2d", std::to_string(two.pullback));
  RecordProperty("pullback_3d", std::to_string(three.pullback));
  RecordProperty("energy_drift_3d", std::to_string(three.energy_drift));
}
