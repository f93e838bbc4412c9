#pragma once
// Convection term v·∇f of the discrete Boltzmann equation by the second-order NND scheme (a TVD
// upwind scheme with the minmod limiter): for a velocity component v the flux derivative at cell i
// along a direction of stride s is built from the limited slopes σ = minmod(Δ−, Δ+) of the upwind
// cells. Needs two ghost cells on each side.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace shockfield::dbm {

/// The argument of smaller magnitude when a and b have the same sign, else 0; written without
/// branches so that loops over cells vectorise.
inline double minmod(double a, double b) {
  return 0.5 * (std::copysign(1.0, a) + std::copysign(1.0, b)) * std::min(std::abs(a), std::abs(b));
}

/// Limited slope of f at p (neighbours at ±s).
inline double limited_slope(const double* p, std::ptrdiff_t s) {
  return minmod(p[0] - p[-s], p[s] - p[0]);
}

/// h ∂f/∂x at p by NND, upwinded for a velocity of sign Upwind (+1, −1; 0 gives 0), given the
/// limited slopes: slope[0] of cell p, slope[±ss] of its neighbours p[±s]. The sign is a template
/// parameter so that loops over cells carry no branch and vectorise.
template <int Upwind>
inline double nnd_difference(const double* p, std::ptrdiff_t s, const double* slope,
                             std::ptrdiff_t ss) {
  if constexpr (Upwind > 0) {
    return (p[0] + 0.5 * slope[0]) - (p[-s] + 0.5 * slope[-ss]);
  } else if constexpr (Upwind < 0) {
    return (p[s] - 0.5 * slope[ss]) - (p[0] - 0.5 * slope[0]);
  } else {
    return 0.0;
  }
}

/// The NND value at the face between p[0] and p[s], reconstructed from the upwind cell: p[0]
/// when the flow goes towards +s (from_low), else p[s].
inline double nnd_face_value(const double* p, std::ptrdiff_t s, bool from_low) {
  return from_low ? p[0] + 0.5 * limited_slope(p, s) : p[s] - 0.5 * limited_slope(p + s, s);
}

/// nnd_difference with the slopes it needs computed on the spot: the difference of the two face
/// values of the cell.
template <int Upwind>
inline double nnd_difference(const double* p, std::ptrdiff_t s) {
  if constexpr (Upwind == 0)
    return 0.0;
  else
    return nnd_face_value(p, s, Upwind > 0) - nnd_face_value(p - s, s, Upwind > 0);
}

}  // namespace shockfield::dbm
