#pragma once
// Convection term v·∇f of the discrete Boltzmann equation by the second-order NND scheme (a TVD
// upwind scheme with the minmod limiter): for a velocity component v the flux derivative at cell i
// along a direction of stride s is built from the limited slopes σ = minmod(Δ−, Δ+) of the upwind
// cells. Needs two ghost cells on each side.
#include <cmath>
#include <cstddef>

namespace shockfield::dbm {

inline double minmod(double a, double b) {
  if (a * b <= 0.0) return 0.0;
  return std::abs(a) < std::abs(b) ? a : b;
}

/// Limited slope of f at p (neighbours at ±s).
inline double limited_slope(const double* p, std::ptrdiff_t s) {
  return minmod(p[0] - p[-s], p[s] - p[0]);
}

/// v ∂f/∂x at p by NND with upwinding on the sign of v; h is the grid spacing.
inline double nnd_derivative(const double* p, std::ptrdiff_t s, double v, double h) {
  if (v == 0.0) return 0.0;
  if (v > 0.0) {
    const double right = p[0] + 0.5 * limited_slope(p, s);
    const double left = p[-s] + 0.5 * limited_slope(p - s, s);
    return v * (right - left) / h;
  }
  const double right = p[s] - 0.5 * limited_slope(p + s, s);
  const double left = p[0] - 0.5 * limited_slope(p, s);
  return v * (right - left) / h;
}

}  // namespace shockfield::dbm
