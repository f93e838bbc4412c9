// Field statistics, spectra, vector calculus and particle binning on cases with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/analysis/field_statistics.hpp"
#include "shockfield/analysis/gaussian_random_field.hpp"
#include "shockfield/analysis/particle_binning.hpp"
#include "shockfield/analysis/spectral_statistics.hpp"
#include "shockfield/analysis/vector_calculus.hpp"

namespace sa = shockfield::analysis;
constexpr double pi = std::numbers::pi;

TEST(Statistics, MomentsAndHistogramOfKnownData) {
  auto f = sa::GridField::filled(5, 1, 1, 0.0);
  f.values = {1, 2, 3, 4, 100};
  f.is_void = {0, 0, 0, 0, 1};  // void cells are skipped
  const auto m = sa::moments(f);
  EXPECT_EQ(m.count, 4u);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.std, std::sqrt(1.25));
  EXPECT_NEAR(m.skewness, 0.0, 1e-15);
  EXPECT_NEAR(m.kurtosis, (2 * 1.5 * 1.5 * 1.5 * 1.5 + 2 * 0.0625) / 4 / (1.25 * 1.25), 1e-14);
  const auto h = sa::histogram(f, 3, 1.0, 4.0);
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{1, 1, 2}));  // last bin holds its upper edge
}

TEST(Statistics, GaussianFieldMomentsAndCorrelation) {
  const auto g = sa::gaussian_random_field(256, 256, 1, 4.0, 5);
  const auto m = sa::moments(g.field);
  EXPECT_NEAR(m.mean, 0.0, 0.1);
  EXPECT_NEAR(m.std, 1.0, 0.1);
  EXPECT_NEAR(m.skewness, 0.0, 0.1);
  EXPECT_NEAR(m.kurtosis, 3.0, 0.2);
  const auto c = sa::correlation_function(g.field);  // ≈ exp(−r²/(2ℓ²))
  EXPECT_DOUBLE_EQ(c.values[0], 1.0);
  EXPECT_NEAR(c.values[4], std::exp(-0.5 * c.x[4] * c.x[4] / 16.0), 0.08);
}

TEST(Statistics, StructureFactorOfOneModeAndDomainSize) {
  // Θ = cos(2π x · 8 / 64): all power in the shell |k| = 2π · 8 / 64 → R = 64 / 8 = 8.
  auto f = sa::GridField::filled(64, 64, 1, 0.0);
  for (std::size_t y = 0; y < 64; ++y)
    for (std::size_t x = 0; x < 64; ++x) f.values[f.index(x, y)] = std::cos(2 * pi * 8.0 * x / 64.0);
  const auto s = sa::structure_factor(f);
  double total = 0.0;
  for (std::size_t i = 0; i < s.x.size(); ++i) total += s.values[i] * double(s.count[i]);
  EXPECT_NEAR(total, 0.5 * 64 * 64, 1e-6);  // Parseval: Σ_k S(k) = Σ_x δΘ² = N/2
  EXPECT_NEAR(sa::characteristic_size(f), 8.0, 1e-9);
}

TEST(VectorCalculus, LinearAndRotationalFields) {
  // v = (2x + y, 3y − x): div = 5, curl_z = −1 − 1 = −2 (exact for central differences).
  auto vx = sa::GridField::filled(8, 6, 1, 0.0), vy = vx;
  vx.spacing = vy.spacing = {0.5, 0.5, 1.0};
  for (std::size_t y = 0; y < 6; ++y)
    for (std::size_t x = 0; x < 8; ++x) {
      const double px = 0.5 * x, py = 0.5 * y;
      vx.values[vx.index(x, y)] = 2 * px + py;
      vy.values[vy.index(x, y)] = 3 * py - px;
    }
  const auto div = sa::divergence(vx, vy, nullptr, false);
  const auto curl = sa::curl_2d(vx, vy, false);
  for (std::size_t i = 0; i < div.size(); ++i) {
    EXPECT_NEAR(div.values[i], 5.0, 1e-12);
    EXPECT_NEAR(curl.values[i], -2.0, 1e-12);
  }
  // 3D rigid rotation about z with ω = 1: v = (−y, x, 0), ∇×v = (0, 0, 2), ∇·v = 0.
  auto wx = sa::GridField::filled(5, 5, 5, 0.0), wy = wx, wz = wx;
  for (std::size_t z = 0; z < 5; ++z)
    for (std::size_t y = 0; y < 5; ++y)
      for (std::size_t x = 0; x < 5; ++x) {
        wx.values[wx.index(x, y, z)] = -double(y);
        wy.values[wy.index(x, y, z)] = double(x);
      }
  const auto r = sa::curl_3d(wx, wy, wz, false);
  const auto d3 = sa::divergence(wx, wy, &wz, false);
  for (std::size_t i = 0; i < wx.size(); ++i) {
    EXPECT_NEAR(r[0].values[i], 0.0, 1e-12);
    EXPECT_NEAR(r[2].values[i], 2.0, 1e-12);
    EXPECT_NEAR(d3.values[i], 0.0, 1e-12);
  }
}

TEST(Binning, MeanPerCellAndVoidForEmptyCells) {
  auto grid = sa::GridField::filled(3, 2, 1, 0.0);
  grid.spacing = {2.0, 2.0, 1.0};
  grid.origin = {-1.0, 0.0, 0.0};
  const std::vector<shockfield::Vec3> p{{-0.5, 0.5, 0}, {0.5, 1.5, 0}, {1.5, 0.1, 0}, {9, 9, 0}};
  const std::vector<double> q{1.0, 3.0, 10.0, 99.0};
  const auto f = sa::bin_particles(p, q, grid);
  EXPECT_DOUBLE_EQ(f.values[f.index(0, 0)], 2.0);  // two particles, mean
  EXPECT_DOUBLE_EQ(f.values[f.index(1, 0)], 10.0);
  EXPECT_EQ(f.void_count(), 4u);  // the particle at (9, 9) is outside
  EXPECT_TRUE(f.void_at(f.index(2, 1)));
  const auto s = sa::bin_particles(p, q, grid, sa::BinReduction::sum);
  EXPECT_DOUBLE_EQ(s.values[s.index(0, 0)], 4.0);
}
