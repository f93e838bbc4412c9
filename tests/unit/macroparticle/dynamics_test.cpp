// Dynamics of the macroparticle model on the MD engine: NVE conserves energy, the Langevin bath
// of eqs 19–22 holds its temperature with Maxwellian velocities, and thread counts agree.
#include <gtest/gtest.h>
#include <omp.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/rng.hpp"
#include "shockfield/core/units.hpp"
#include "unit/macroparticle/rod_fixture.hpp"

namespace shockfield::macroparticle {
namespace {

double total_energy(const Rod& rod) {
  const RodMeasures m = rod.measure();
  return m.kinetic + m.potential;
}

TEST(MacroparticleDynamics, NveConservesEnergy) {
  const MacroparticleCase c = fixture::read_case(fixture::free_box("steps = 2000"));
  Rod rod(c);
  // Random velocities of 1 % of the bond energy per particle (engine units: D = M = 1).
  auto& a = rod.sim().atoms;
  for (std::size_t i = 0; i < a.nlocal; ++i)
    for (int d = 0; d < 3; ++d) a.v[i][d] = 0.01 * rng::normal(3, i, static_cast<std::uint64_t>(d)) / std::sqrt(units::metal::mvv2e);
  rod.sim().setup(false);
  const double e0 = total_energy(rod), k0 = rod.measure().kinetic;
  double worst = 0;
  for (int s = 0; s < c.steps; ++s) {
    rod.advance(false);
    worst = std::max(worst, std::abs(total_energy(rod) - e0));
  }
  // Velocity Verlet at Δt = 0.2 of the stable step (ω_max Δt = 0.4): the shadow-energy
  // fluctuation is ~(ωΔt)²/24 ≈ 0.7 % of the vibrational energy; allow 2 % of the initial kinetic
  // energy, with no drift beyond it over 2000 steps.
  EXPECT_LT(worst, 0.02 * k0) << "initial kinetic " << k0 << " J";
  EXPECT_GT(k0, 0.0);
}

TEST(MacroparticleDynamics, LangevinHoldsTheTemperatureWithMaxwellianVelocities) {
  // γΔt/M = 0.02 at Δt = 0.05 of the stable step: the damping time is 50 steps, the bath is at
  // 1e16 K (k_B T = 1.8e-7 of the bond energy: a harmonic crystal).
  const MacroparticleCase probe = fixture::read_case(fixture::free_box("steps = 1"));
  const double dt = 0.05 * probe.law.stable_time_step();
  const double friction = 0.02 * probe.law.particle_mass / dt;
  const double bath = 1e16;
  const MacroparticleCase c = fixture::read_case(fixture::free_box(
      fmt::format("steps = 1\ndt = {:.17g}", dt), fmt::format("[langevin]\ntemperature = 1e16\nseed = 11\nfriction = {:.17g}", friction)));
  Rod rod(c);
  for (int s = 0; s < 1000; ++s) rod.advance(false);  // 20 damping times
  const std::size_t n = rod.size();
  double t_sum = 0, m2 = 0, m4 = 0;
  long long count = 0;
  const int samples = 40;
  for (int k = 0; k < samples; ++k) {
    for (int s = 0; s < 100; ++s) rod.advance(false);  // two damping times apart: near independent
    t_sum += rod.measure().temperature;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        const double v2 = std::pow(rod.sim().atoms.v[i][d], 2);
        m2 += v2;
        m4 += v2 * v2;
        ++count;
      }
  }
  // The measured temperature uses 3N − 3 degrees of freedom while the bath holds all 3N.
  const double expected = bath * 3.0 * static_cast<double>(n) / (3.0 * static_cast<double>(n) - 3.0);
  // One sample of T has a relative spread √(2/3N) = 4.5 % (N = 324 here); 40 samples: 0.7 %;
  // allow 3 % (four standard errors).
  EXPECT_NEAR(t_sum / samples / expected, 1.0, 0.03);
  // Maxwellian: the kurtosis ⟨v⁴⟩/⟨v²⟩² of a Gaussian component is 3; its standard error over
  // 3N·40 = 38 880 values is √(96/n) ≈ 0.05; allow 0.2.
  m2 /= static_cast<double>(count);
  m4 /= static_cast<double>(count);
  EXPECT_NEAR(m4 / (m2 * m2), 3.0, 0.2);
}

TEST(MacroparticleDynamics, PairDissipationHoldsTheTemperatureAndConservesMomentum) {
  // Eq 8 alone: 12μΔt/M = 0.12, so a particle relaxes against its neighbours in ~10 steps; the
  // slowest (long-wavelength) modes of the 3×3×3-cell cube take ~N^(2/3) times longer.
  const MacroparticleCase probe = fixture::read_case(fixture::free_box("steps = 1"));
  const double dt = 0.05 * probe.law.stable_time_step();
  const double mu = 0.01 * probe.law.particle_mass / dt;
  const MacroparticleCase c = fixture::read_case(fixture::free_box(
      fmt::format("steps = 1\ndt = {:.17g}", dt), fmt::format("[langevin]\ntemperature = 1e16\nseed = 5\npair_viscosity = {:.17g}", mu)));
  Rod rod(c);
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < rod.size(); ++i) p += rod.sim().atoms.v[i];
    return p;
  };
  for (int s = 0; s < 2000; ++s) rod.advance(false);
  double t_sum = 0;
  const int samples = 40;
  for (int k = 0; k < samples; ++k) {
    for (int s = 0; s < 100; ++s) rod.advance(false);
    t_sum += rod.measure().temperature;
  }
  // The pair forces leave the centre of mass at rest: the 3N − 3 internal degrees of freedom
  // hold the bath temperature. 4 %: the sampling error (0.7 %) plus correlation between samples.
  EXPECT_NEAR(t_sum / samples / 1e16, 1.0, 0.04);
  // Action equals reaction: the momentum stays zero up to round-off (velocities ~ 1e-4 here).
  EXPECT_LT(momentum().norm(), 1e-12);
}

std::vector<Vec3> run_with_threads(int threads) {
  omp_set_num_threads(threads);
  const MacroparticleCase c = fixture::read_case(
      fixture::rod(4, 4, 40.0, 0.0005, "dt = 1e-7") + "[langevin]\ntemperature = 1e17\nfriction = 0.05\nseed = 3\n"
      "[plasticity]\nyield_strain = 0.0001\nhardening = [0.1]\n");
  Rod rod(c);
  for (long long s = 0; s < c.steps; ++s) rod.advance(s % 50 == 0);
  omp_set_num_threads(1);
  EXPECT_GT(rod.bonds()->size(), 100u);  // the plastic bond table is in play
  return {rod.sim().atoms.x.begin(), rod.sim().atoms.x.begin() + static_cast<long>(rod.size())};
}

TEST(MacroparticleDynamics, OneAndTwoThreadsAgree) {
  const auto one = run_with_threads(1), two = run_with_threads(2);
  ASSERT_EQ(one.size(), two.size());
  double worst = 0;
  for (std::size_t i = 0; i < one.size(); ++i) worst = std::max(worst, (one[i] - two[i]).norm());
  // The random forces are keyed on (seed, step, particle id) and the bond table on particle ids,
  // not on threads; the only
  // difference is the order of the pair-force sums of md's pair loop (round-off, 1e-16 of a
  // force), grown over 125 steps of an elastic (non-chaotic) rod: 1e-10 r0 is far above it.
  EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace shockfield::macroparticle
