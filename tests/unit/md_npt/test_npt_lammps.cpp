// NPT against LAMMPS `fix npt` on the same system (500 Cu_u3 atoms, 300 K, dt 2 fs, τ_T 0.1 ps,
// τ_P 0.5 ps): the mean volume at 0 bar (iso: the thermally expanded crystal) and at 10 GPa
// (aniso) agrees with the LAMMPS reference of tests/fixtures/lammps_npt within sampling error.
#include <gtest/gtest.h>

#include <cstdio>

#include "npt_fixture.hpp"

using namespace shockfield;
using namespace shockfield::md;
using namespace shockfield::md::npt_test;

namespace {

struct Sampled {
  Estimate volume, temperature, pressure;
};

/// Equilibrates, then samples V, T and P every 20 steps.
Sampled sample(Simulation& sim, int equilibration, int samples) {
  run(sim, equilibration);
  std::vector<double> v, t, p;
  for (int k = 0; k < samples; ++k) {
    run(sim, 20);
    const ThermoState th = sim.thermo();
    v.push_back(th.volume);
    t.push_back(th.temperature);
    p.push_back(th.pressure);
  }
  return {block_estimate(v, 10), block_estimate(t, 10), block_estimate(p, 10)};
}

void expect_lammps_volume(const Sampled& ours, const std::string& name, double pressure) {
  const auto ref = lammps_reference(name);
  const Estimate& lmp = ref.at("volume");
  // Tolerance: 4 combined standard errors (block estimates of both runs), at least 0.02% of V
  // for the uncertainty of the error estimates themselves (10 and 20 blocks).
  const double tol = std::max(4.0 * std::hypot(ours.volume.error, lmp.error), 2e-4 * lmp.mean);
  std::printf("%s: V = %.2f ± %.2f A^3 (LAMMPS %.2f ± %.2f), T = %.1f K, P = %.0f bar\n", name.c_str(),
              ours.volume.mean, ours.volume.error, lmp.mean, lmp.error, ours.temperature.mean, ours.pressure.mean);
  EXPECT_NEAR(ours.volume.mean, lmp.mean, tol) << name << ": ours " << ours.volume.mean << " ± "
                                               << ours.volume.error << ", LAMMPS " << lmp.mean << " ± " << lmp.error;
  // The thermostat and barostat reach their targets (500 atoms: T fluctuates by ~11 K, P by ~2 kbar).
  EXPECT_NEAR(ours.temperature.mean, 300.0, 4.0 * ours.temperature.error + 3.0) << name;
  EXPECT_NEAR(ours.pressure.mean, pressure, 4.0 * ours.pressure.error + 150.0) << name;
}

}  // namespace

TEST(NptLammps, ZeroPressureIsoGivesTheThermallyExpandedCrystal) {
  // From the 0 K lattice constant: the crystal must expand by ~0.5% in length to get there.
  Simulation sim = copper_npt(5, 3.615, 300.0, settings(0.0, true));
  const double v0 = sim.box.volume();
  const Sampled ours = sample(sim, 2500, 300);
  EXPECT_GT(ours.volume.mean / v0, 1.01);
  expect_lammps_volume(ours, "cu_300K_0bar", 0.0);
}

TEST(NptLammps, TenGigapascalAnisoMatchesLammpsVolume) {
  Simulation sim = copper_npt(5, 3.615, 300.0, settings(1e5, false));
  const Sampled ours = sample(sim, 2500, 300);
  expect_lammps_volume(ours, "cu_300K_10GPa", 1e5);
}
