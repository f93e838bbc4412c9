#pragma once
// Grid shape functions of the material point method, one axis at a time. The 2D bilinear and 3D
// trilinear functions of Xu et al. (2015) eq. 9, N_i = (1/8)(1 + ξξ_i)(1 + ηη_i)(1 + ζζ_i), are tensor
// products of the 1D hat N(r) = 1 − |r|/h; the GIMP option (uniform GIMP, Bardenhagen & Kober,
// CMES 5 (2004) 477, eq. 39) convolves the hat with the particle's box of half-width l_p < h/2,
// which removes most of the cell-crossing noise of the linear functions.
//
// A shape type reports `support` (nodes per axis it may touch) and `evaluate(x, h, half)`: the
// first node index and the weights and derivatives for `support` consecutive nodes, for a
// coordinate x measured from the grid origin, cell size h and particle half-width `half`.
#include <array>
#include <cmath>
#include <concepts>

namespace shockfield::mpm {

struct Weights1D {
  int base = 0;                     ///< index of the first node
  int count = 1;                    ///< nodes used along this axis
  std::array<double, 3> w{1, 0, 0};   ///< N(x) for nodes base, base+1, ...
  std::array<double, 3> dw{0, 0, 0};  ///< dN/dx [1/m]
};

template <class S>
concept ShapeFunction = requires(double x) {
  { S::support } -> std::convertible_to<int>;
  { S::evaluate(x, x, x) } -> std::same_as<Weights1D>;
};

/// Linear hat (eq. 9 along one axis).
struct LinearShape {
  static constexpr int support = 2;
  static Weights1D evaluate(double x, double h, double /*half*/) {
    const double xi = x / h;
    const double b = std::floor(xi);
    const double f = xi - b;
    return {static_cast<int>(b), 2, {1.0 - f, f, 0.0}, {-1.0 / h, 1.0 / h, 0.0}};
  }
};

/// Uniform GIMP: particle box [x − l, x + l], l = half < h/2, so at most three nodes. The pieces
/// are evaluated with the reciprocals 1/h and 1/(hl) and selected without branches (the inner
/// loop of every step's stencil evaluation).
struct GimpShape {
  static constexpr int support = 3;
  static Weights1D evaluate(double x, double h, double half) {
    Weights1D out;
    out.count = 3;
    out.base = static_cast<int>(std::floor((x - half) / h));
    const double inv_h = 1.0 / h, inv_hl = 1.0 / (h * half);
    for (int k = 0; k < 3; ++k) {
      const double r = x - (out.base + k) * h;  // particle minus node position
      const double a = std::abs(r), sgn = r < 0.0 ? -1.0 : 1.0, g = h + half - a;
      const double w_in = 1.0 - (r * r + half * half) * (0.5 * inv_hl), dw_in = -r * inv_hl;  // |r| < l
      const double w_mid = 1.0 - a * inv_h, dw_mid = -sgn * inv_h;                           // l <= |r| <= h − l
      const double w_out = g * g * (0.25 * inv_hl), dw_out = -sgn * g * (0.5 * inv_hl);     // h − l < |r| < h + l
      const bool in = a < half, mid = a <= h - half, out_ = a < h + half;
      out.w[static_cast<std::size_t>(k)] = in ? w_in : mid ? w_mid : out_ ? w_out : 0.0;
      out.dw[static_cast<std::size_t>(k)] = in ? dw_in : mid ? dw_mid : out_ ? dw_out : 0.0;
    }
    return out;
  }
};

}  // namespace shockfield::mpm
