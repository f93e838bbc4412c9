#pragma once
// Points sampled on shapes with a known area and volume, for the surface tests (rolling ball,
// pivoting ball, packing-sculpting) and the CGAL alpha-shape comparison.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace shockfield::geometry::testing {

/// n points uniform on the sphere of radius r about c (normalised Gaussian triples).
inline std::vector<std::array<double, 3>> sphere(std::size_t n, double r, std::array<double, 3> c, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<std::array<double, 3>> p(n);
  for (auto& x : p) {
    const double a = g(rng), b = g(rng), z = g(rng), s = r / std::sqrt(a * a + b * b + z * z);
    x = {c[0] + a * s, c[1] + b * s, c[2] + z * s};
  }
  return p;
}

/// n points uniform in area on the torus of radii R (centre line, about z) and a (tube): the tube
/// angle is accepted with probability (R + a cos v)/(R + a).
inline std::vector<std::array<double, 3>> torus(std::size_t n, double R, double a, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * std::numbers::pi), w(0, 1);
  std::vector<std::array<double, 3>> p;
  while (p.size() < n) {
    const double t = u(rng), v = u(rng);
    if (w(rng) > (R + a * std::cos(v)) / (R + a)) continue;
    p.push_back({(R + a * std::cos(v)) * std::cos(t), (R + a * std::cos(v)) * std::sin(t), a * std::sin(v)});
  }
  return p;
}

/// Two unit spheres of n points each, centres (±(1 + gap/2), 0, 0).
inline std::vector<std::array<double, 3>> two_spheres(std::size_t n, double gap) {
  auto p = sphere(n, 1.0, {-1.0 - 0.5 * gap, 0, 0}, 3);
  const auto q = sphere(n, 1.0, {1.0 + 0.5 * gap, 0, 0}, 4);
  p.insert(p.end(), q.begin(), q.end());
  return p;
}

}  // namespace shockfield::geometry::testing
