// Minkowski functionals of Gaussian random fields against the analytic expectations
// (Adler 1981, "The Geometry of Random Fields", Thm 4.1.1; Tomita 1986, Prog. Theor. Phys. 76,
// 952). With ν = Θ_th / σ and λ = ⟨(∂_x Θ)²⟩ / σ², per unit area (2D) or volume (3D):
//   A = V = ½ erfc(ν/√2),  L/area = (√λ / 2) e^{−ν²/2},  S/vol = (2/π) √λ e^{−ν²/2},
//   χ/area = λ ν e^{−ν²/2} / (2π)^{3/2},  b̄/vol = λ ν e^{−ν²/2} / (2π)^{3/2},
//   χ/vol = λ^{3/2} (ν² − 1) e^{−ν²/2} / (2π)².
// Tolerance: 4 standard errors of the mean over independent realisations (sampling error) plus
// 3% of the curve's peak for the lattice estimators (correlation length 5 cells in 2D, 3 in 3D).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "shockfield/analysis/gaussian_random_field.hpp"
#include "shockfield/analysis/minkowski.hpp"

namespace sa = shockfield::analysis;
constexpr double pi = std::numbers::pi;

namespace {

std::vector<double> levels() {
  std::vector<double> t;
  for (int i = -12; i <= 12; ++i) t.push_back(0.25 * i);
  return t;
}

// mean and standard error over realisations of quantity q[r][k]
void compare(const std::vector<std::vector<double>>& q, const std::vector<double>& nu,
             const std::function<double(double)>& expected, const char* name) {
  double peak = 0.0;
  for (double v : nu) peak = std::max(peak, std::abs(expected(v)));
  for (std::size_t k = 0; k < nu.size(); ++k) {
    double mean = 0.0, var = 0.0;
    for (const auto& r : q) mean += r[k] / double(q.size());
    for (const auto& r : q) var += (r[k] - mean) * (r[k] - mean) / double(q.size() - 1);
    const double se = std::sqrt(var / double(q.size()));
    EXPECT_NEAR(mean, expected(nu[k]), 4.0 * se + 0.03 * peak) << name << " at ν = " << nu[k];
  }
}

}  // namespace

TEST(GaussianField, Functionals2DFollowAdlerTomita) {
  const std::vector<double> nu = levels();
  std::vector<std::vector<double>> area, length, euler;
  double lambda = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto g = sa::gaussian_random_field(256, 256, 1, 5.0, seed);
    lambda = g.lambda;
    const double cells = double(g.field.size());
    std::vector<double> a, l, c;
    for (const auto& f : sa::minkowski_2d(g.field, nu))  // periodic, 8-connected
      a.push_back(f.area_fraction), l.push_back(f.boundary_length / cells),
          c.push_back(double(f.euler) / cells);
    area.push_back(a), length.push_back(l), euler.push_back(c);
  }
  compare(area, nu, [](double v) { return 0.5 * std::erfc(v / std::sqrt(2.0)); }, "A");
  compare(length, nu, [&](double v) { return 0.5 * std::sqrt(lambda) * std::exp(-0.5 * v * v); },
          "L");
  compare(euler, nu, [&](double v) {
    return lambda * v * std::exp(-0.5 * v * v) / std::pow(2 * pi, 1.5);
  }, "chi");
}

TEST(GaussianField, Functionals3DFollowAdlerTomita) {
  const std::vector<double> nu = levels();
  std::vector<std::vector<double>> volume, surface, breadth, euler;
  double lambda = 0.0;
  for (std::uint64_t seed = 11; seed <= 16; ++seed) {
    const auto g = sa::gaussian_random_field(64, 64, 64, 3.0, seed);
    lambda = g.lambda;
    const double cells = double(g.field.size());
    std::vector<double> v, s, b, c;
    for (const auto& f : sa::minkowski_3d(g.field, nu))  // periodic, (26, 6)
      v.push_back(f.volume_fraction), s.push_back(f.surface_area / cells),
          b.push_back(f.mean_breadth / cells), c.push_back(double(f.euler) / cells);
    volume.push_back(v), surface.push_back(s), breadth.push_back(b), euler.push_back(c);
  }
  const auto gauss = [](double v) { return std::exp(-0.5 * v * v); };
  compare(volume, nu, [](double v) { return 0.5 * std::erfc(v / std::sqrt(2.0)); }, "V");
  compare(surface, nu, [&](double v) { return 2.0 / pi * std::sqrt(lambda) * gauss(v); }, "S");
  compare(breadth, nu, [&](double v) { return lambda * v * gauss(v) / std::pow(2 * pi, 1.5); },
          "b");
  compare(euler, nu, [&](double v) {
    return std::pow(lambda, 1.5) * (v * v - 1.0) * gauss(v) / (4 * pi * pi);
  }, "chi");
}
