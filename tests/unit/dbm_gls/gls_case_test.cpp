// The density range a GLS quench is expected to reach (gls_case.hpp, expected_density_range): it sets the
// Δt check (capillary bound through ρ_liquid, diffusion through ζ/ρ_vapour) and the run's
// gls_expected_rho_* values. Above T_c it is the range of the initial field on the cells; below, widened
// to the Maxwell construction (Xu et al. 2015, §4.3).
#include <gtest/gtest.h>

#include <algorithm>

#include "shockfield/dbm/coexistence.hpp"
#include "shockfield/dbm/gls_case.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

Lattice unit_box(int n) {
  Lattice l;
  l.nx = l.ny = n, l.dx = l.dy = 1.0 / n;
  return l;
}

// The smallest and largest density of the initial state on the cell centres, as Simulation::initialize
// evaluates it.
std::pair<double, double> initial_density_range(const Quench& q, const Lattice& l) {
  const QuenchNoise xi = q.noise_field(l);
  double lo = 1e300, hi = -1e300;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const double rho = q.state(xi, l.x(i), l.y(j)).rho;
      lo = std::min(lo, rho), hi = std::max(hi, rho);
    }
  return {lo, hi};
}

GlsCaseSpec quench_spec(double T, double noise_wavelength) {
  GlsCaseSpec spec;
  spec.quench.rho0 = 1.0, spec.quench.T = T, spec.quench.noise = 0.05, spec.quench.seed = 7;
  spec.quench.noise_wavelength = noise_wavelength;
  return spec;
}

}  // namespace

TEST(DbmGlsCase, SupercriticalRangeIsTheInitialFieldsOnTheCells) {
  // Band-limited noise (the phase-separation example's: λ = 1/16, seed 7) reaches |ξ| well above 1
  // (rms 1/√3, a Gaussian-like sum of ~400 modes): the former range ρ0(1 ± noise) = [0.95, 1.05], the bound
  // of white noise per cell, missed the initial field's own extremes. Both sides must match to round-off.
  const Lattice lattice = unit_box(64);
  GlsCaseSpec spec = quench_spec(1.2, 1.0 / 16);
  expected_density_range(spec, lattice);
  const auto [lo, hi] = initial_density_range(spec.quench, lattice);
  EXPECT_DOUBLE_EQ(spec.rho_vapour, lo);
  EXPECT_DOUBLE_EQ(spec.rho_liquid, hi);
  EXPECT_GT(spec.rho_liquid, 1.05);  // what the per-cell bound got wrong
  EXPECT_LT(spec.rho_vapour, 0.95);
  EXPECT_LT(spec.rho_liquid, 1.0 + 0.05 * spec.quench.noise_field(lattice).bound());  // inside the rigorous bound
}

TEST(DbmGlsCase, WhiteNoiseRangeStaysInsideTheNoiseAmplitude) {
  const Lattice lattice = unit_box(32);
  GlsCaseSpec spec = quench_spec(1.2, 0.0);
  expected_density_range(spec, lattice);
  const auto [lo, hi] = initial_density_range(spec.quench, lattice);
  EXPECT_DOUBLE_EQ(spec.rho_vapour, lo);
  EXPECT_DOUBLE_EQ(spec.rho_liquid, hi);
  EXPECT_GE(spec.rho_vapour, 0.95);
  EXPECT_LE(spec.rho_liquid, 1.05);
}

TEST(DbmGlsCase, SubcriticalRangeIsWidenedToMaxwellCoexistence) {
  // T = 0.85 T_c: the coexisting densities (0.32, 1.81 for vdW) lie outside the initial field's range.
  GlsCaseSpec spec = quench_spec(0.85, 1.0 / 16);
  expected_density_range(spec, unit_box(64));
  const Coexistence co = maxwell_construction(materials::VanDerWaals{}, 0.85);
  EXPECT_DOUBLE_EQ(spec.rho_vapour, co.rho_vapour);
  EXPECT_DOUBLE_EQ(spec.rho_liquid, co.rho_liquid);
}
