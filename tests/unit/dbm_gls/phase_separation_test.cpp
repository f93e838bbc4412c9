// Phase-separation diagnostics of the GLS model (Xu et al. 2015, §4.3): the quench initial state, one
// sample of D, L, R against quantities computed here independently, and t_SD / D_max from the
// peak of D(t). The long K study is not a unit test (see docs/theory/dbm.md for its status).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "shockfield/core/error.hpp"

#include "shockfield/dbm/phase_separation.hpp"
#include "unit/dbm_gls/gls_setup.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

TEST(DbmPhaseSeparation, QuenchIsSeededNoiseAroundTheMeanDensity) {
  Lattice lattice;
  lattice.nx = lattice.ny = 32, lattice.dx = lattice.dy = 1.0 / 32;
  Quench q;
  q.noise = 0.05;
  const QuenchNoise xi = q.noise_field(lattice);
  double mean = 0, lo = 1e9, hi = -1e9;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const Macro m = q.state(xi, lattice.x(i), lattice.y(j));
      EXPECT_EQ(m.rho, q.state(xi, lattice.x(i), lattice.y(j)).rho);
      mean += m.rho / 1024, lo = std::min(lo, m.rho), hi = std::max(hi, m.rho);
    }
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_GE(lo, 0.95);
  EXPECT_LE(hi, 1.05);
  Quench other = q;
  other.seed = 2;
  EXPECT_NE(other.state(other.noise_field(lattice), 0.5, 0.5).rho, q.state(xi, 0.5, 0.5).rho);
}

namespace {

Lattice unit_box(int n) {
  Lattice l;
  l.nx = l.ny = n, l.dx = l.dy = 1.0 / n;
  return l;
}

// ξ of the n² interior cells (i + n·j).
std::vector<double> noise_on(const Quench& q, const Lattice& l) {
  const QuenchNoise xi = q.noise_field(l);
  std::vector<double> v(static_cast<std::size_t>(l.nx) * l.ny);
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) v[i + static_cast<std::size_t>(l.nx) * j] = xi(l.x(i), l.y(j));
  return v;
}

}  // namespace

TEST(DbmPhaseSeparation, BandLimitedNoiseIsTheSameFieldOnEveryGrid) {
  // The modes' noise is a function of (x, y) and the box alone: the 64² and 128² grids (and 96²,
  // whose Δx = 1/96 rounds) see the same value at any point (round-off of a ~300-term cosine sum),
  // the same Fourier coefficients on the modes both hold, nothing above the cutoff |k| ≤ 2π·16, a
  // zero mean and the mean square 1/3 of white noise (exact on a grid that resolves the modes).
  // White noise (wavelength 0) fails each of these: its 64² and 128² fields differ point by point.
  Quench q;
  q.seed = 7, q.noise_wavelength = 1.0 / 16;
  const Lattice coarse = unit_box(64), fine = unit_box(128), odd = unit_box(96);
  const QuenchNoise a = q.noise_field(coarse), b = q.noise_field(fine), c = q.noise_field(odd);
  EXPECT_GT(a.modes(), 300u);  // π·16²/2 ≈ 402 modes in the half disc
  for (const double x : {0.0, 0.123, 0.5, 0.77})
    for (const double y : {0.0, 0.31, 0.9}) {
      EXPECT_NEAR(a(x, y), b(x, y), 1e-12);
      EXPECT_NEAR(a(x, y), c(x, y), 1e-12);
    }
  const std::vector<double> va = noise_on(q, coarse), vb = noise_on(q, fine);
  const PeriodicSpectral sa(64, 64, 1.0 / 64, 1.0 / 64), sb(128, 128, 1.0 / 128, 1.0 / 128);
  const auto fa = sa.forward(va), fb = sb.forward(vb);
  // Coefficient of mode (m, n) of the field (half-spectrum rows n ≥ 0, then n < 0 at size + n), over the
  // cell count and with the phase of the half-cell offset of the cell centres, e^{iπ(m + n)/size}, removed.
  const auto coef = [](const std::vector<std::complex<double>>& s, int size, int m, int n) {
    const std::complex<double> shift = std::polar(1.0, -std::numbers::pi * (m + n) / size);
    return shift * s[m + static_cast<std::size_t>(size / 2 + 1) * (n >= 0 ? n : size + n)] /
           static_cast<double>(size * size);
  };
  double beyond = 0.0, diff = 0.0;
  for (int n = -63; n <= 64; ++n)
    for (int m = 0; m <= 64; ++m) {
      const bool inside = m * m + n * n <= 256;
      if (!inside) beyond = std::max(beyond, std::abs(coef(fb, 128, m, n)));
      if (inside && m <= 31 && std::abs(n) <= 31) diff = std::max(diff, std::abs(coef(fa, 64, m, n) - coef(fb, 128, m, n)));
    }
  EXPECT_LT(beyond, 1e-13);
  EXPECT_LT(diff, 1e-13);
  for (const auto& [v, xi] : {std::pair{&va, &a}, std::pair{&vb, &b}}) {
    double mean = 0, square = 0;
    for (const double x : *v) mean += x / v->size(), square += x * x / v->size();
    EXPECT_NEAR(mean, 0.0, 1e-13);
    EXPECT_NEAR(square, 1.0 / 3.0, 1e-12);
    const auto [lo, hi] = xi->extremes_on_cells();  // the values the initial state takes
    EXPECT_EQ(lo, *std::min_element(v->begin(), v->end()));
    EXPECT_EQ(hi, *std::max_element(v->begin(), v->end()));
  }
  q.noise_wavelength = 0.0;  // white noise: the two grids draw different fields
  const QuenchNoise wa = q.noise_field(coarse), wb = q.noise_field(fine);
  EXPECT_GT(std::abs(wa(0.123, 0.31) - wb(0.123, 0.31)), 1e-3);
}

TEST(DbmPhaseSeparation, NoiseShorterThanTwoCellsIsRefused) {
  Quench q;
  q.noise_wavelength = 1.0 / 40;
  EXPECT_NO_THROW(q.noise_field(unit_box(80)));
  EXPECT_THROW(q.noise_field(unit_box(64)), InputError);
}

TEST(DbmPhaseSeparation, SampleOfAStripe) {
  // ρ = 1 + 0.3 sin(2πx): two straight boundaries of length 1 at ρ = 1 (L = 2), R = 2π/k₁ = 1,
  // no TNE in the initial equilibrium state, the variance 0.3²/2.
  gls_testing::GlsCase c;
  c.nx = c.ny = 32, c.K = 1e-3, c.tau = 1e-3, c.dt = 2e-4;
  auto run = gls_testing::make_gls(c, [](double x, double) {
    return Macro{1.0 + 0.3 * std::sin(2 * std::numbers::pi * x), 0, 0, 0.9};
  });
  const PhaseSample s = sample_phase_separation(*run.sim, *run.force, 1.0);
  EXPECT_NEAR(s.boundary_length, 2.0, 0.12);  // lattice-line estimate: axis-aligned lines 5% short
  EXPECT_NEAR(s.domain_size, 1.0, 1e-9);
  EXPECT_NEAR(s.density_variance, 0.045, 1e-9);
  EXPECT_NEAR(s.D, 0.0, 1e-12);
  EXPECT_NEAR(s.mass, 1.0, 1e-12);
  for (int k = 0; k < 5; ++k) run.sim->step();
  const PhaseSample later = sample_phase_separation(*run.sim, *run.force, 1.0);
  EXPECT_GT(later.D, 1e-6);  // the force drives the state off equilibrium
  EXPECT_LE(later.D, later.D_force + later.D_gradient + 1e-15);  // triangle inequality (eq. 30)
}

TEST(DbmPhaseSeparation, SpinodalEndIsThePeakOfD) {
  std::vector<PhaseSample> samples;
  for (int i = 0; i <= 20; ++i) {
    PhaseSample s;
    s.t = 0.1 * i;
    s.D = std::exp(-std::pow(s.t - 1.2, 2));
    s.boundary_length = 5 - std::abs(s.t - 1.1);
    s.domain_size = 0.1 + s.t;
    samples.push_back(s);
  }
  const SpinodalEnd e = spinodal_end(samples);
  EXPECT_NEAR(e.t_sd, 1.2, 1e-12);
  EXPECT_NEAR(e.D_max, 1.0, 1e-12);
  EXPECT_NEAR(e.R_sd, 1.3, 1e-12);
  EXPECT_NEAR(e.t_L_max, 1.1, 1e-12);
  EXPECT_NEAR(e.L_max, 5.0, 1e-12);
}
