#include "shockfield/pd/riemann.hpp"

#include <algorithm>
#include <cmath>

namespace shockfield::pd {
namespace {

// One side's contribution to g and to its derivative, on the piece where sign(u − u_side) = σ.
struct Piece {
  double value, slope, curvature;  // term, d term/du, coefficient of (u − u_c)²
};

Piece side_term(const RiemannSide& side, double u, double sigma) {
  const double w = u - side.u;
  return {side.rho * (side.a + sigma * side.s * w) * w, side.rho * (side.a + 2.0 * sigma * side.s * w),
          sigma * side.rho * side.s};
}

double g(const RiemannSide& l, const RiemannSide& r, double u) {
  return r.p - l.p + r.rho * (r.a + r.s * std::abs(u - r.u)) * (u - r.u) +
         l.rho * (l.a + l.s * std::abs(u - l.u)) * (u - l.u);
}

}  // namespace

RiemannSolution dukowicz_two_shock(const RiemannSide& l, const RiemannSide& r) {
  const double lo = std::min(l.u, r.u), hi = std::max(l.u, r.u);
  const double g_lo = g(l, r, lo), g_hi = g(l, r, hi);
  // The piece holding the root, and the break point to expand about.
  double uc, probe;
  if (g_lo >= 0.0) {
    uc = lo, probe = lo - 1.0;
  } else if (g_hi <= 0.0) {
    uc = hi, probe = hi + 1.0;
  } else {
    uc = lo, probe = 0.5 * (lo + hi);
  }
  const Piece pl = side_term(l, uc, probe > l.u ? 1.0 : -1.0);
  const Piece pr = side_term(r, uc, probe > r.u ? 1.0 : -1.0);
  const double g0 = r.p - l.p + pl.value + pr.value;
  const double slope = pl.slope + pr.slope;  // > 0: every term increases with u
  const double curvature = pl.curvature + pr.curvature;
  const double disc = std::max(slope * slope - 4.0 * curvature * g0, 0.0);
  const double u = uc - 2.0 * g0 / (slope + std::sqrt(disc));
  return {r.p + r.rho * (r.a + r.s * std::abs(u - r.u)) * (u - r.u), u};
}

}  // namespace shockfield::pd
