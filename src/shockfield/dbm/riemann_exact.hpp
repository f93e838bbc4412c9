#pragma once
// Exact solution of the Riemann problem of the 1D Euler equations for an ideal gas (Toro,
// "Riemann Solvers and Numerical Methods for Fluid Dynamics", ch. 4): the star-region pressure
// by Newton iteration on the pressure function, then the self-similar solution sampled at x/t.
// The reference for the DBM shock tubes.

namespace shockfield::dbm {

struct Primitive {
  double rho = 1.0, u = 0.0, p = 1.0;
};

struct RiemannStar {
  double p = 0.0, u = 0.0;          // star-region pressure and velocity
  double rho_left = 0.0, rho_right = 0.0;  // densities left and right of the contact
};

class ExactRiemann {
 public:
  /// InputError for non-positive densities or pressures, or a vacuum-generating jump.
  ExactRiemann(const Primitive& left, const Primitive& right, double gamma);
  const RiemannStar& star() const { return star_; }
  /// State at similarity coordinate ξ = (x − x0)/t.
  Primitive sample(double xi) const;
  /// Speed of the right-going shock (NaN if the right wave is a rarefaction).
  double right_shock_speed() const;

 private:
  // Pressure function f_K(p) and its derivative for side K (Toro eqs. 4.6–4.7).
  void pressure_function(double p, const Primitive& s, double c, double& f, double& df) const;

  Primitive left_, right_;
  double gamma_, c_left_, c_right_;
  RiemannStar star_;
};

}  // namespace shockfield::dbm
