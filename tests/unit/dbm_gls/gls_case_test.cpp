// The density range a GLS quench is expected to reach (gls_case.hpp, expected_density_range): it sets the
// Δt check (capillary bound through ρ_liquid, diffusion through ζ/ρ_vapour) and the run's
// gls_expected_rho_* values. Above T_c it is the range of the initial field on the cells; below, widened
// to the Maxwell construction (Xu et al. 2015, §4.3). read_quench checks the noise amplitude against the
// same initial field on the cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
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

namespace {

// read_quench of the phase-separation example's noise (ρ0 = 1, band-limited λ = 1/16, seed 7) on 64², at
// amplitude `noise`.
Quench read_example_quench(double noise) {
  const Config root = Config::parse(fmt::format("[initial]\nrho0 = 1.0\nT = 0.85\nseed = 7\nnoise_wavelength = "
                                                "0.0625\nnoise = {}\n", noise), "quench.toml");
  return read_quench(root.table("initial"), GlsSettings{}, unit_box(64));
}

}  // namespace

TEST(DbmGlsCase, QuenchNoiseIsCheckedAgainstTheFieldOnTheCells) {
  // The field's own extremes on the cells bound the initial densities (as in expected_density_range). The
  // former check used the rigorous bound s Σ|A_mn| = 12.98 of this noise, ~5.8x its max|ξ| on the cells, and
  // refused any noise above 1/12.98 = 0.077 at ρ0 = 1 although the field stayed positive.
  const Quench q = read_example_quench(0.05);
  const auto [xi_min, xi_max] = q.noise_field(unit_box(64)).extremes_on_cells();
  ASSERT_GT(-xi_min, 1.5);  // the noise these amplitudes are chosen for: |ξ| between 1.5 and 3
  ASSERT_LT(-xi_min, 3.0);
  ASSERT_LT(xi_max, 3.0);
  // 0.2: densities 1 + 0.2 ξ in [0.4, 1.6], accepted now; 1 − 0.2·12.98 < 0 was refused before.
  const Quench wide = read_example_quench(0.2);
  EXPECT_DOUBLE_EQ(wide.noise, 0.2);
  const auto [rho_vapour, rho_liquid] = std::pair{1.0 + 0.2 * xi_min, 1.0 + 0.2 * xi_max};
  EXPECT_GT(rho_vapour, 0.0);
  EXPECT_LT(rho_liquid, 3.0);  // the vdW limit 1/b
  // 0.7: 1 + 0.7 ξ_min < 0 — a negative density on some cell, refused by both checks, under the key.
  ASSERT_LT(1.0 + 0.7 * xi_min, 0.0);
  try {
    read_example_quench(0.7);
    ADD_FAILURE() << "noise 0.7 gives a negative density and must be refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("noise"), std::string::npos) << what;
    EXPECT_NE(what.find("not positive"), std::string::npos) << what;
  }
}
