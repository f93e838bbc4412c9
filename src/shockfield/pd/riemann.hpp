#pragma once
// Interface pressure of a Riemann problem between two points by Dukowicz's non-iterative
// two-shock approximation (J. Comput. Phys. 61 (1985) 119-137), as Liu et al. (2025) eq. 15 uses it.
//
// Each side is joined to the interface state (p*, u*) by a shock with impedance
// W = ρ(a + s|u* − u|) (the linear Us-Up Hugoniot, used for rarefactions as well):
//   right:  p* = p_R + ρ_R(a_R + s_R|u* − u_R|)(u* − u_R)
//   left:   p* = p_L − ρ_L(a_L + s_L|u* − u_L|)(u* − u_L)
// Equating them gives g(u*) = 0 with g strictly increasing and piecewise quadratic between the
// break points u_L, u_R (seed eq. 15 writes the same function with the squares completed). The
// root is found without iteration: g at the sorted break points picks the piece, then the
// quadratic of that piece is solved in the form w = −2g(u_c)/(g'(u_c) + √(g'(u_c)² − 4A·g(u_c)))
// about a break point u_c, which has no cancellation and tends to the acoustic (s = 0) solution.
namespace shockfield::pd {

struct RiemannSide {
  double p;    ///< pressure (positive in compression) [Pa]
  double u;    ///< velocity along the left→right direction [m/s]
  double rho;  ///< density [kg/m³]
  double a;    ///< sound speed (impedance intercept) [m/s]
  double s;    ///< Us-Up slope [-]
};

struct RiemannSolution {
  double p;  ///< interface pressure p* [Pa]
  double u;  ///< interface velocity u* [m/s]
};

RiemannSolution dukowicz_two_shock(const RiemannSide& left, const RiemannSide& right);

}  // namespace shockfield::pd
