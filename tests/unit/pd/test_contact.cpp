// The short-range contact force (contact.hpp, LAMMPS's PERI rule): its value for one pair, forces
// against finite differences of the potential energy (bonds + contact, PMB and LPS), and two
// bodies that bounce apart only because of it, with momentum and energy balances; the faces of a
// zero-width cut that come into contact when they slide.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <memory>

#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

constexpr double kSpacing = 5e-4, kHorizon = 2.6 * kSpacing, kDensity = 2200.0;
constexpr double kBulk = 14.9e9, kShear = 8.94e9;
const double kMicromodulus = LpsModel{kBulk, kShear, 3}.contact_micromodulus(kHorizon);  // 18K/(πδ⁴)

// Two n×n×n blocks along x whose facing planes are `gap` spacings apart.
PointCloud two_blocks(int n, double gap) {
  PointCloud a = lattice_cloud(3, {n, n, n}, kSpacing);
  const PointCloud b = lattice_cloud(3, {n, n, n}, kSpacing, Vec3((n - 1 + gap) * kSpacing, 0.0, 0.0));
  a.x.insert(a.x.end(), b.x.begin(), b.x.end());
  a.volume.insert(a.volume.end(), b.volume.begin(), b.volume.end());
  return a;
}

template <class Model>
std::unique_ptr<BondForce<Model>> make_force(const PointCloud& cloud, const Family& family, bool contact) {
  if constexpr (Model::uses_dilatation)
    return std::make_unique<BondForce<Model>>(cloud, family, LpsModel{kBulk, kShear, 3},
                                              Influence(Influence::Kind::inverse), CriticalStretch{}, contact);
  else
    return std::make_unique<BondForce<Model>>(cloud, family, PmbModel{kMicromodulus}, Influence(), CriticalStretch{},
                                              contact);
}

}  // namespace

// Two bonded points (r0 = ΔX) squeezed to 0.8 ΔX, inside their reach min(0.9·r0, 1.35·ΔX) = 0.9 ΔX:
// the force with contact minus the force without is LAMMPS's 15c·V_j·(d − r)/δ, repulsive.
TEST(ShortRangeContact, PairForceIsLammpsFormula) {
  const PointCloud cloud = lattice_cloud(3, {2, 1, 1}, kSpacing);
  const Family family = build_family(cloud, kHorizon, VolumeCorrection::linear);
  std::vector<Vec3> f_on, f_off;
  const std::vector<Vec3> y{Vec3::Zero(), Vec3(0.8 * kSpacing, 0.0, 0.0)}, v(2, Vec3::Zero());
  make_force<PmbModel>(cloud, family, true)->compute({y, v, 0.0}, f_on);
  make_force<PmbModel>(cloud, family, false)->compute({y, v, 0.0}, f_off);
  const double volume = kSpacing * kSpacing * kSpacing;
  const double expected = 15.0 * kMicromodulus * volume * (0.9 - 0.8) * kSpacing / kHorizon;  // pushes 0 to −x
  EXPECT_NEAR(f_on[0].x() - f_off[0].x(), -expected, 1e-12 * expected);
  EXPECT_NEAR(f_on[1].x() - f_off[1].x(), expected, 1e-12 * expected);
  EXPECT_EQ(f_on[0].y(), 0.0);
}

// V_i·f_i = −∂U/∂y_i by central differences (h = 1e-6 ΔX), on a deformed block with pairs in
// contact (12% squeezed along x, nearest neighbours inside 0.9 ΔX: 38 pairs), for PMB and LPS. The
// tolerance 1e-6 of the largest force is far above the differences' truncation and round-off
// (~1e-9 here) and far below a missing factor or term.
template <class Model>
void check_energy_gradient() {
  const PointCloud cloud = lattice_cloud(3, {4, 4, 4}, kSpacing);
  const Family family = build_family(cloud, kHorizon, VolumeCorrection::linear);
  auto force = make_force<Model>(cloud, family, true);
  std::vector<Vec3> y = cloud.x;
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = Vec3(0.88 * y[i].x(), y[i].y(), y[i].z()) + 0.02 * kSpacing * Vec3(std::sin(1.3 * i), std::cos(0.7 * i), std::sin(2.1 * i + 1));
  const std::vector<Vec3> v(y.size(), Vec3::Zero());
  std::vector<Vec3> f;
  force->compute({y, v, 0.0}, f);
  ASSERT_GE(force->contact()->active_pairs(y), 30u);
  double largest = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) largest = std::max(largest, cloud.volume[i] * f[i].norm());
  const double h = 1e-6 * kSpacing;
  for (std::size_t i : {0u, 5u, 21u, 42u, 63u})
    for (int d = 0; d < 3; ++d) {
      std::vector<Vec3> plus = y, minus = y;
      plus[i][d] += h;
      minus[i][d] -= h;
      const double gradient = (force->potential_energy(plus) - force->potential_energy(minus)) / (2.0 * h);
      EXPECT_NEAR(cloud.volume[i] * f[i][d], -gradient, 1e-6 * largest) << force->name() << " point " << i << " axis " << d;
    }
}
TEST(ShortRangeContact, PmbForcesAreEnergyGradient) { check_energy_gradient<PmbModel>(); }
TEST(ShortRangeContact, LpsForcesAreEnergyGradient) { check_energy_gradient<LpsModel>(); }

// Two 4×4×4 blocks 3 ΔX apart (beyond the horizon 2.6 ΔX: no bond joins them; the geometry of
// tests/fixtures/lammps_peri/in.bounce) approach at ±50 m/s. With contact they bounce: each
// block's mean velocity changes sign (restitution 0.89 PMB, 0.95 LPS: the rest goes into the
// blocks' vibration); total momentum stays zero to round-off; kinetic + bond + contact energy
// stays within 0.2% of the initial kinetic energy. That error is the integrator's: measured
// 1.1e-2, 2.6e-3, 7.7e-4, 1.2e-4 (PMB) at 1/2, 1/4, 1/8, 1/16 of the stable step, O(Δt²); run at
// 1/8. Without contact they pass through each other.
template <class Model>
void bounce() {
  const int n = 4;
  const PointCloud cloud = two_blocks(n, 3.0);
  const Family family = build_family(cloud, kHorizon, VolumeCorrection::linear);
  const std::size_t half = cloud.size() / 2;
  for (std::size_t i = 0; i < half; ++i)
    for (int b = family.begin(i); b < family.end(i); ++b) ASSERT_LT(static_cast<std::size_t>(family.neighbor[b]), half);
  double block_velocity[2][2];  // [contact][block]
  for (int contact = 0; contact < 2; ++contact) {
    auto owned = make_force<Model>(cloud, family, contact == 1);
    BondForce<Model>& force = *owned;
    Simulation sim(cloud, family, std::move(owned), {kDensity});
    for (std::size_t i = 0; i < cloud.size(); ++i) sim.velocities()[i] = Vec3(i < half ? 50.0 : -50.0, 0.0, 0.0);
    sim.setup();
    const double dt = 0.125 * sim.stable_step();
    const double mass = kDensity * kSpacing * kSpacing * kSpacing * static_cast<double>(half);
    const double e0 = sim.kinetic_energy() + force.potential_energy(sim.positions());
    double drift = 0.0;
    std::size_t most_pairs = 0;
    // 30 µs: the gap closes to the reach 1.35 ΔX after 7 µs, the contact lasts a few µs.
    while (sim.time() < 30e-6) {
      sim.step(dt);
      drift = std::max(drift, std::abs(sim.kinetic_energy() + force.potential_energy(sim.positions()) - e0));
      if (contact) most_pairs = std::max(most_pairs, force.contact()->active_pairs(sim.positions()));
      EXPECT_LT(sim.momentum().norm(), 1e-12 * mass * 50.0) << force.name() << " step " << sim.step_count();
    }
    for (int b = 0; b < 2; ++b) {
      double sum = 0.0;
      for (std::size_t i = b * half; i < (b + 1) * half; ++i) sum += sim.velocities()[i].x();
      block_velocity[contact][b] = sum / static_cast<double>(half);
    }
    if (contact) {
      EXPECT_LT(drift, 2e-3 * e0) << force.name();
      EXPECT_GT(most_pairs, 0u);
      EXPECT_EQ(force.contact()->active_pairs(sim.positions()), 0u) << "still in contact at the end";
      std::printf("%s bounce: energy drift %.3g of the initial, up to %zu pairs in contact, block velocities %.4g "
                  "and %.4g m/s (restitution %.3f)\n",
                  force.name().c_str(), drift / e0, most_pairs, block_velocity[1][0], block_velocity[1][1],
                  -block_velocity[1][0] / 50.0);
    }
  }
  EXPECT_LT(block_velocity[1][0], -5.0);  // bounced back
  EXPECT_GT(block_velocity[1][1], 5.0);
  EXPECT_GT(block_velocity[0][0], 45.0);  // passed through
  EXPECT_LT(block_velocity[0][1], -45.0);
}
TEST(ShortRangeContact, PmbBlocksBounceApart) { bounce<PmbModel>(); }
TEST(ShortRangeContact, LpsBlocksBounceApart) { bounce<LpsModel>(); }

// The contact sums run over each point's partners in index order, whoever built the list and on
// however many threads: the bounce with contact acting is bitwise the same on 1 and 2 threads.
TEST(ShortRangeContact, ResultsDoNotDependOnThreadCount) {
  const PointCloud cloud = two_blocks(4, 3.0);
  const Family family = build_family(cloud, kHorizon, VolumeCorrection::linear);
  std::vector<Vec3> y[2];
  std::size_t pairs = 0;
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    auto owned = make_force<PmbModel>(cloud, family, true);
    BondForce<PmbModel>& force = *owned;
    Simulation sim(cloud, family, std::move(owned), {kDensity});
    for (std::size_t i = 0; i < cloud.size(); ++i) sim.velocities()[i] = Vec3(i < cloud.size() / 2 ? 50.0 : -50.0, 0, 0);
    for (int s = 0; s < 120; ++s) sim.step(1e-7), pairs = std::max(pairs, force.contact()->active_pairs(sim.positions()));
    y[t] = sim.positions();
  }
  omp_set_num_threads(1);
  EXPECT_GT(pairs, 0u);
  for (std::size_t i = 0; i < y[0].size(); ++i) ASSERT_EQ(y[0][i], y[1][i]) << i;
}

// The faces of a zero-width pre-crack (two rows of a 2D lattice ΔX apart) sliding past each other
// by u along the cut (docs/theory/pd.md, "Short-range contact"): the pair straight across stays out
// of its reach 0.9ΔX, a diagonal pair comes into its reach 0.9·√2ΔX once (ΔX − u)² + ΔX² < 1.62ΔX²,
// i.e. u > 0.2126ΔX. Then the contact force pushes the upper face up (opening the cut) and back
// against the slide; this is what lowered the Kalthoff–Winkler crack angle (examples/pd_kalthoff_winkler).
TEST(ShortRangeContact, SlidingCutFacesComeIntoContactAfterAFifthOfTheSpacing) {
  const int n = 8;
  const PointCloud cloud = lattice_cloud(2, {n, 2, 1}, kSpacing);  // row y = 0 (lower face), row y = ΔX (upper)
  ShortRangeContact contact(cloud, kMicromodulus, kHorizon);
  const auto slid = [&](double u) {
    std::vector<Vec3> y = cloud.x;
    for (std::size_t i = 0; i < y.size(); ++i)
      if (cloud.x[i].y() > 0.5 * kSpacing) y[i].x() += u * kSpacing;
    return y;
  };
  const double threshold = 1.0 - std::sqrt(2.0 * 0.81 - 1.0);  // 0.2126
  EXPECT_EQ(contact.active_pairs(slid(0.0)), 0u);
  EXPECT_EQ(contact.active_pairs(slid(threshold - 0.005)), 0u);
  const std::vector<Vec3> y = slid(threshold + 0.05);
  EXPECT_EQ(contact.active_pairs(y), static_cast<std::size_t>(n - 1));  // one diagonal pair per column but the last
  contact.update(y);
  const Vec3 f = contact.force_density(n + n / 2, y);  // an upper-face point in the middle
  EXPECT_GT(f.y(), 0.0);                              // the faces are pushed apart
  EXPECT_LT(f.x(), 0.0);                              // and the slide (+x) is held back
}
