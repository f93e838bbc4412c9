#pragma once
// Convection term v·∇f of the discrete Boltzmann equation by the second-order NND scheme (a TVD
// upwind scheme with the minmod limiter): for a velocity component v the flux derivative at cell i
// along a direction of stride s is the difference of the face values reconstructed from the
// upwind cells with the limited slopes σ = minmod(Δ−, Δ+). Needs two ghost cells on each side.
#include <algorithm>
#include <cstddef>

namespace shockfield::dbm {

/// The argument of smaller magnitude when a and b have the same sign, else 0: the median of
/// (0, a, b), four min/max operations without branches so that loops over cells vectorise.
inline double minmod(double a, double b) {
  return std::max(std::min(a, b), std::min(std::max(a, b), 0.0));
}

/// Limited slope of f at p (neighbours at ±s).
inline double limited_slope(const double* p, std::ptrdiff_t s) {
  return minmod(p[0] - p[-s], p[s] - p[0]);
}

/// The NND value of cell p at its downwind face for a flow of sign Upwind along s: p[0] + ½σ at
/// the face towards +s (Upwind > 0), p[0] − ½σ at the face towards −s (Upwind < 0). Each face
/// value serves two cells (h ∂f/∂x = face(p) − face(p − s) for Upwind > 0, face(p + s) − face(p)
/// for Upwind < 0), so row kernels compute it once per cell. The sign is a template parameter so
/// that loops over cells carry no branch and vectorise.
template <int Upwind>
inline double downwind_face(const double* p, std::ptrdiff_t s) {
  static_assert(Upwind == 1 || Upwind == -1);
  return p[0] + (Upwind > 0 ? 0.5 : -0.5) * limited_slope(p, s);
}

/// The NND value at the face between p[0] and p[s], reconstructed from the upwind cell: p[0]
/// when the flow goes towards +s (from_low), else p[s].
inline double nnd_face_value(const double* p, std::ptrdiff_t s, bool from_low) {
  return from_low ? downwind_face<1>(p, s) : downwind_face<-1>(p + s, s);
}

}  // namespace shockfield::dbm
