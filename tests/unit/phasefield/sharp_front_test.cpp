// The sharp-front option (phasefield/sharp_front.hpp): Ṙ = c₀ + s(n − 1)D/R against its closed form
// t(R) for both signs in 2D and 3D, the fixed radius of each sign, the shape-mode growth rate
// against a perturbed circle moved by the same law, and the domains on the grid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "shockfield/core/error.hpp"
#include "shockfield/phasefield/sharp_front.hpp"

namespace shockfield::phasefield {
namespace {

double radius_after(const SharpFrontLaw& law, double R, double dt, int steps) {
  for (int i = 0; i < steps && R > 0.0; ++i) R = law.advance(R, dt);
  return R;
}

// RK4 on u = R² against t(R): the time the closed form gives for the integrated radius must be
// the time integrated, to 1e-9 (RK4's error at dt = 0.02 is ~1e-11 here), and the error of R at
// dt = 0.4 divided by that at 0.2 must be 16 ± 4 (fourth order) where it is above round-off (1e-9 R₀:
// the four c₀ = 0.7 cases; c₀ = 0 is exact, u̇ constant, and c₀ = −0.05 nearly so) — for both laws,
// c₀ of both signs and zero, 2D and 3D.
TEST(SharpFront, RadiusFollowsTheClosedForm) {
  int orders = 0;
  for (const FrontLaw kind : {FrontLaw::paper, FrontLaw::allen_cahn})
    for (const int dim : {2, 3})
      for (const double c0 : {0.7, -0.05, 0.0}) {
        const SharpFrontLaw law{kind, c0, 1.5, dim};
        const double R0 = kind == FrontLaw::paper || c0 > 0 ? 12.0 : 30.0, t = 20.0;
        const double R1 = radius_after(law, R0, 0.02, 1000);
        SCOPED_TRACE(::testing::Message() << front_law_name(kind) << " dim " << dim << " c0 " << c0 << " R " << R1);
        ASSERT_GT(R1, 0.0);
        EXPECT_NEAR(law.time_between(R0, R1), t, 1e-9 * t);
        // The error of R itself, against the closed form solved for R by bisection.
        double lo = std::min(R0, R1) * 0.9, hi = std::max(R0, R1) * 1.1;
        const bool increasing = law.time_between(R0, hi) > law.time_between(R0, lo);
        for (int i = 0; i < 200; ++i) {
          const double mid = 0.5 * (lo + hi);
          ((law.time_between(R0, mid) < t) == increasing ? lo : hi) = mid;
        }
        const double e1 = std::abs(radius_after(law, R0, 0.4, 50) - lo), e2 = std::abs(radius_after(law, R0, 0.2, 100) - lo);
        if (e1 > 1e-9 * R0) {
          EXPECT_NEAR(e1 / e2, 16.0, 4.0) << e1 << " " << e2;
          ++orders;
        }
      }
  EXPECT_GE(orders, 4);  // the order was measured
}

// Allen–Cahn sign: R* = (n − 1)D/c₀ is unstable (1 % above grows, 1 % below shrinks and vanishes at
// the closed form's t(R₀ → 0), within one step); paper sign with c₀ < 0: R* = (n − 1)D/|c₀| is
// stable, domains from both sides tend to it; paper sign with c₀ ≥ 0: every domain grows.
TEST(SharpFront, FixedRadiusOfEachSign) {
  const SharpFrontLaw ac{FrontLaw::allen_cahn, 0.5, 2.0, 3};
  const double Rs = ac.fixed_radius();
  EXPECT_DOUBLE_EQ(Rs, 8.0);
  EXPECT_GT(radius_after(ac, 1.01 * Rs, 0.01, 2000), 1.02 * Rs);
  const double t_end = ac.time_between(0.99 * Rs, 0.0);
  std::vector<SharpDomain> d{{1, {0, 0, 0}, 0.99 * Rs}, {2, {0, 0, 0}, 1.01 * Rs}};
  int step = 0;
  while (d.size() == 2 && step < 100000) advance_domains(ac, 0.01, d), ++step;
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].track, 2);
  EXPECT_NEAR(step * 0.01, t_end, 0.01) << "vanished at step " << step;
  // c₀ = 0: R² = R₀² − 2(n − 1)Dt exactly (u̇ constant), gone at R₀²/(2(n − 1)D) = 100/8 = 12.5
  // (removed at the step that reaches it or the next: u = 0 to round-off at the step's end).
  std::vector<SharpDomain> shrinking{{1, {0, 0, 0}, 10.0}};
  const SharpFrontLaw curvature_only{FrontLaw::allen_cahn, 0.0, 2.0, 3};
  for (int i = 0; i < 1249; ++i) advance_domains(curvature_only, 0.01, shrinking);
  ASSERT_EQ(shrinking.size(), 1u);
  EXPECT_NEAR(shrinking[0].radius, std::sqrt(100.0 - 8.0 * 12.49), 1e-9);
  advance_domains(curvature_only, 0.01, shrinking);
  if (!shrinking.empty()) {
    EXPECT_LT(shrinking[0].radius, 1e-5);  // u = R² left by round-off (~1e-12 after 1250 steps)
    advance_domains(curvature_only, 0.01, shrinking);
  }
  EXPECT_TRUE(shrinking.empty());

  const SharpFrontLaw paper{FrontLaw::paper, -0.5, 2.0, 3};
  EXPECT_DOUBLE_EQ(paper.fixed_radius(), 8.0);
  // Approached as e^{−t/16} (dṘ/dR = −(n − 1)D/R*² = −1/16): from 6 or 12 away, 1e-9 after t = 400.
  EXPECT_NEAR(radius_after(paper, 2.0, 0.01, 40000), 8.0, 1e-9);
  EXPECT_NEAR(radius_after(paper, 20.0, 0.01, 40000), 8.0, 1e-9);
  const SharpFrontLaw growing{FrontLaw::paper, 0.0, 2.0, 2};
  EXPECT_TRUE(std::isinf(growing.fixed_radius()));
  EXPECT_NEAR(radius_after(growing, 1.0, 0.01, 1000), std::sqrt(1.0 + 4.0 * 10.0), 1e-9);  // R² = R₀² + 2Dt
}

// δ̇/δ = sD(l − 1)(l + n − 1)/R²: l = 0 is dṘ/dR (by central differences), l = 1 a translation (0),
// l ≥ 2 positive and growing as l² for the paper's sign, negative for the Allen–Cahn sign.
TEST(SharpFront, ShapeModeGrowthRate) {
  for (const int dim : {2, 3}) {
    const SharpFrontLaw paper{FrontLaw::paper, 0.3, 1.0, dim}, ac{FrontLaw::allen_cahn, 0.3, 1.0, dim};
    const double R = 5.0, h = 1e-5;
    EXPECT_NEAR(paper.mode_growth_rate(0, R), (paper.rate(R + h) - paper.rate(R - h)) / (2 * h), 1e-8);
    EXPECT_NEAR(ac.mode_growth_rate(0, R), (ac.rate(R + h) - ac.rate(R - h)) / (2 * h), 1e-8);
    EXPECT_EQ(paper.mode_growth_rate(1, R), 0.0);
    for (int l = 2; l < 200; ++l) {
      EXPECT_GT(paper.mode_growth_rate(l, R), paper.mode_growth_rate(l - 1, R));
      EXPECT_DOUBLE_EQ(ac.mode_growth_rate(l, R), -paper.mode_growth_rate(l, R));
    }
    EXPECT_NEAR(paper.mode_growth_rate(1000, R) / (1000.0 * 1000.0), 1.0 / (R * R), 0.01 / (R * R));
  }
}

// A perturbed circle ρ(θ) = R + δ cos(lθ) moved by v = c₀ + sDκ as a polar graph (ρ_t = v √(1 + ρ_θ²/ρ²),
// κ = (ρ² + 2ρ_θ² − ρρ_θθ)/(ρ² + ρ_θ²)^{3/2}, derivatives by the discrete Fourier series of 32
// markers, RK4): the amplitude of mode l must grow by exp(∫ σ_l(R(t)) dt) to 2e-3 (δ/R = 1e-4,
// second-order terms ~1e-4 relative) for l = 2, 3, 5 and both signs.
TEST(SharpFront, PerturbedCircleFollowsTheModeGrowthRate) {
  constexpr int N = 32;
  const double pi = std::numbers::pi;
  auto derivatives = [&](const std::vector<double>& r, std::vector<double>& d1, std::vector<double>& d2) {
    d1.assign(N, 0.0), d2.assign(N, 0.0);
    for (int k = 1; k < N / 2; ++k) {
      double a = 0, b = 0;
      for (int j = 0; j < N; ++j) a += r[j] * std::cos(2 * pi * k * j / N), b += r[j] * std::sin(2 * pi * k * j / N);
      a *= 2.0 / N, b *= 2.0 / N;
      for (int j = 0; j < N; ++j) {
        const double c = std::cos(2 * pi * k * j / N), s = std::sin(2 * pi * k * j / N);
        d1[j] += k * (b * c - a * s), d2[j] -= k * k * (a * c + b * s);
      }
    }
  };
  for (const FrontLaw kind : {FrontLaw::paper, FrontLaw::allen_cahn})
    for (const int l : {2, 3, 5}) {
      const SharpFrontLaw law{kind, 0.2, 1.0, 2};
      const double R0 = 5.0, delta0 = 1e-4 * R0, dt = 0.002, t_end = 1.0;
      std::vector<double> r(N), d1, d2;
      for (int j = 0; j < N; ++j) r[j] = R0 + delta0 * std::cos(2 * pi * l * j / N);
      auto speed = [&](const std::vector<double>& q) {
        derivatives(q, d1, d2);
        std::vector<double> out(N);
        for (int j = 0; j < N; ++j) {
          const double g = q[j] * q[j] + d1[j] * d1[j];
          const double kappa = (g + d1[j] * d1[j] - q[j] * d2[j]) / std::pow(g, 1.5);
          out[j] = (law.c0 + law.sign() * law.D * kappa) * std::sqrt(1.0 + d1[j] * d1[j] / (q[j] * q[j]));
        }
        return out;
      };
      double R = R0, exponent = 0.0;
      for (int step = 0; step < static_cast<int>(t_end / dt + 0.5); ++step) {
        auto add = [&](const std::vector<double>& k, double f) {
          std::vector<double> o(r);
          for (int j = 0; j < N; ++j) o[j] += f * k[j];
          return o;
        };
        const auto k1 = speed(r), k2 = speed(add(k1, dt / 2)), k3 = speed(add(k2, dt / 2)), k4 = speed(add(k3, dt));
        for (int j = 0; j < N; ++j) r[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        // ∫σ_l dt by Simpson's rule on the law's R(t).
        const double Rm = law.advance(R, dt / 2), R1 = law.advance(R, dt);
        exponent += dt / 6 * (law.mode_growth_rate(l, R) + 4 * law.mode_growth_rate(l, Rm) + law.mode_growth_rate(l, R1));
        R = R1;
      }
      double amplitude = 0.0;
      for (int j = 0; j < N; ++j) amplitude += 2.0 / N * r[j] * std::cos(2 * pi * l * j / N);
      SCOPED_TRACE(::testing::Message() << front_law_name(kind) << " l = " << l << " exponent " << exponent);
      EXPECT_NEAR(amplitude / delta0, std::exp(exponent), 2e-3 * std::exp(exponent));
      EXPECT_EQ(amplitude > delta0, kind == FrontLaw::paper);
    }
}

// The node cover: a sphere of radius 6 on a grid of spacing 0.5 holds its volume/dx³ nodes to 2 %
// (lattice points in a ball of 12 spacings: the count's error is O(R^{3/2}) nodes, 1.2 % for the
// centre on a node), the same across a periodic face; two spheres at distance d overlap in the lens
// π(4R + d)(2R − d)²/12 to 5 % (fewer nodes: a larger relative error).
TEST(SharpFront, NodeCoverMeasuresVolumeAndOverlap) {
  Grid g;
  g.dim = 3, g.n = {48, 48, 48}, g.dx = 0.5;
  const double V = ball_volume(6.0, 3), cell = 0.125, nodes = 48.0 * 48 * 48;
  const NodeCover centred = cover_nodes(g, {{1, {12, 12, 12}, 6.0}}, false);
  EXPECT_NEAR(centred.nodes_inside[0] * cell, V, 0.02 * V);
  const NodeCover wrapped = cover_nodes(g, {{1, {0.0, 23.9, 12}, 6.0}}, true);
  EXPECT_NEAR(wrapped.nodes_inside[0] * cell, V, 0.02 * V);
  EXPECT_NEAR(wrapped.volume_fraction * nodes, static_cast<double>(wrapped.nodes_inside[0]), 0.5);
  double ones = 0;
  for (const double x : wrapped.indicator) ones += x;
  EXPECT_EQ(ones, static_cast<double>(wrapped.nodes_inside[0]));
  const double d = 8.0, lens = std::numbers::pi * (4 * 6.0 + d) * (2 * 6.0 - d) * (2 * 6.0 - d) / 12;
  const NodeCover two = cover_nodes(g, {{1, {8, 12, 12}, 6.0}, {2, {16, 12, 12}, 6.0}}, false);
  EXPECT_NEAR(two.overlap_fraction * nodes * cell, lens, 0.05 * lens);
  EXPECT_NEAR(two.volume_fraction * nodes * cell, 2 * V - lens, 0.02 * (2 * V - lens));
  EXPECT_DOUBLE_EQ(equivalent_radius(ball_volume(3.5, 2), 2), 3.5);
  EXPECT_THROW(sharp_domains({{Domain::Kind::ellipsoid, {0, 0, 0}, {1, 2, 3}}}), InputError);
}

}  // namespace
}  // namespace shockfield::phasefield
