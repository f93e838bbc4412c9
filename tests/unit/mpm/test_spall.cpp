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

// The seed's aluminium made hydrodynamic (σ_Y0 = 1 kPa, no hardening): the pull-back then travels
// at the bulk sound speed c0 that the acoustic formula uses (no elastic precursor to correct for).
materials::SolidMaterial hydrodynamic_al(double spall_strength) {
  auto m = materials::aluminium_seed000();
  m.strength.yield_stress0 = 1e3;
  m.strength.tangent_modulus = 0.0;
  m.spall.strength = spall_strength;
  m.validate();
  return m;
}

struct FreeSurface {
  std::vector<double> t, u;  // time [s], mean v_y of the top particle row [m/s]
  double peak = 0.0, pullback = 0.0, max_damage = 0.0, energy_drift = 0.0;
};

// Mean v_y of the particles within a quarter cell of the highest one (the free face's row).
double top_row_velocity(const mpm::Particles& p) {
  double top = -INFINITY, sum = 0.0;
  int n = 0;
  for (const Vec3& x : p.x) top = std::max(top, x[1]);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i][1] > top - 0.25 * kCell) sum += p.v[i][1], ++n;
  return sum / n;
}

FreeSurface flyer_plate(const materials::SolidMaterial& mat) {
  const double d = kFlyerCells * kCell, width = 2 * kCell;
  mpm::Particles p;
  mpm::add_body(p, 2, {Vec3(0, -d, 0), Vec3(width, 0, 0), kCell / 2, Vec3(0, kSpeed, 0), 0}, mat);
  mpm::add_body(p, 2, {Vec3(0, 0, 0), Vec3(width, 3 * d, 0), kCell / 2, Vec3::Zero(), 0}, mat);
  const auto grid =
      mpm::impact_grid(2, Vec3(0, -d - 10 * kCell, 0), Vec3(width, 3 * d + 20 * kCell, 0), kCell);
  mpm::SimulationOptions opt;
  opt.shape = mpm::ShapeKind::Gimp;
  mpm::Simulation sim(grid, {mat}, std::move(p), opt);
  const double e0 = mpm::totals(sim.particles()).total();
  FreeSurface fs;
  const double end = 7.0 * d / mat.eos.c0;  // arrival at 3d/Us, release at 5d/c, spall signal ~7d/c
  while (sim.time() < end) {
    sim.step();
    fs.t.push_back(sim.time());
    fs.u.push_back(top_row_velocity(sim.particles()));
  }
  // Plateau: the median of u_fs over the 0.5 µs after it first reaches 95 % of v (it rings by a few
  // %). Pull-back: from the plateau to the first minimum after u_fs falls 5 % of v below it.
  std::size_t k = 0;
  while (fs.u[k] < 0.95 * kSpeed) ++k;
  std::vector<double> plateau;
  for (std::size_t i = k; i < fs.u.size() && fs.t[i] < fs.t[k] + 0.5e-6; ++i)
    plateau.push_back(fs.u[i]);
  std::nth_element(plateau.begin(), plateau.begin() + static_cast<long>(plateau.size() / 2),
                   plateau.end());
  fs.peak = plateau[plateau.size() / 2];
  std::size_t m = k;
  while (m + 1 < fs.u.size() && fs.u[m] > fs.peak - 0.05 * kSpeed) ++m;
  while (m + 1 < fs.u.size() && fs.u[m + 1] <= fs.u[m]) ++m;
  fs.pullback = fs.peak - fs.u[m];
  for (const auto& s : sim.particles().state) fs.max_damage = std::max(fs.max_damage, s.damage);
  fs.energy_drift = (mpm::totals(sim.particles()).total() - e0) / e0;
  return fs;
}

}  // namespace

// σ_sp = 0.5 and 1 GPa, both below the ≈ 1.5 GPa tension the 200 m/s impact can reach. The
// acoustic estimate reads low, measured 0.28 and 0.66 GPa here (0.69-0.72·σ_sp at 1 GPa with 40
// or 80 cells per flyer at 170-200 m/s, so not a resolution effect; the same with 4 points per
// cell): about σ_est ≈ 0.77·σ_sp − 0.10 GPa. The criterion fires at the right wave tension (the
// intact neighbours of the first failed points are at −0.47 and −0.97 GPa), and confining the
// failure to one cell does not change it; the relief reaches the free face ~100 ns early, which
// the linear artificial viscosity, diffusing it ahead (C_L = 0.6 reads lower still), would
// explain (examples/mpm_spall/README.md). Hence the tolerances: σ_est within [0.5, 1.1]·σ_sp,
// and the estimate rising with σ_sp (its increase from 0.5 to 1 GPa within [0.6, 1.1]·0.5 GPa),
// which a model failing at a fixed wrong stress, or not at all, would break.
TEST(Spall, FreeSurfacePullbackMeasuresTheSpallStrength) {
  double estimate[2] = {0.0, 0.0};
  const double strengths[2] = {0.5e9, 1.0e9};
  for (int i = 0; i < 2; ++i) {
    const auto al = hydrodynamic_al(strengths[i]);
    const FreeSurface fs = flyer_plate(al);
    EXPECT_NEAR(fs.peak, kSpeed, 0.03 * kSpeed);
    estimate[i] = 0.5 * al.eos.rho0 * al.eos.c0 * fs.pullback;
    EXPECT_GT(estimate[i], 0.5 * strengths[i]);
    EXPECT_LT(estimate[i], 1.1 * strengths[i]);
    EXPECT_EQ(fs.max_damage, 1.0);
    EXPECT_LT(std::abs(fs.energy_drift), 0.01);
    RecordProperty("sigma_est_" + std::to_string(i), std::to_string(estimate[i]));
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
