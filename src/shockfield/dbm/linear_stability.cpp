#include "shockfield/dbm/linear_stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace shockfield::dbm {
namespace {

using Complex = std::complex<double>;
using ComplexVector16 = Eigen::Matrix<Complex, kMoments, 1>;

/// The wave numbers θ = kΔ of one axis: [0, π] for x (A(−k) is the complex conjugate of A(k),
/// same spectrum), [−π, π] for y on a 2D lattice.
std::vector<double> wave_numbers(int resolution, bool full_axis, double largest = std::numbers::pi) {
  std::vector<double> theta;
  const int lo = full_axis ? -resolution : 0;
  for (int m = lo; m <= resolution; ++m) theta.push_back(largest * m / resolution);
  return theta;
}

/// −i S(k) + J: the generator of the semi-discrete perturbation (A = Δt times it).
ComplexMatrix16 generator(const StabilityProblem& p, const RealMatrix16& collision, double theta_x,
                          double theta_y, Stencil stencil) {
  ComplexMatrix16 m = collision.cast<Complex>();
  for (int k = 0; k < kMoments; ++k)
    m(k, k) -= convection_symbol(p.model.vx[k], theta_x, p.dx, stencil) +
               convection_symbol(p.model.vy[k], theta_y, p.dy, stencil);
  return m;
}

ComplexVector16 eigenvalues(const ComplexMatrix16& m) {
  return Eigen::ComplexEigenSolver<ComplexMatrix16>(m, false).eigenvalues();
}

/// Δt is acceptable when no eigenvalue μ of a generator is amplified by one RK3 step faster than
/// the semi-discrete mode itself grows: ln|R(Δtμ)| ≤ (max(Re μ, 0) + tolerance)Δt.
bool time_step_ok(const std::vector<Complex>& mu, double dt, double tolerance) {
  return std::all_of(mu.begin(), mu.end(), [&](Complex m) {
    return std::log(std::abs(rk3_factor(dt * m))) <= (std::max(m.real(), 0.0) + tolerance) * dt;
  });
}

double largest_stable_dt(const std::vector<Complex>& mu, double dt, double tolerance) {
  double lo = 0.0, hi = dt;
  if (time_step_ok(mu, dt, tolerance)) {
    for (lo = dt, hi = 2.0 * dt; time_step_ok(mu, hi, tolerance); lo = hi, hi *= 2.0)
      if (hi > 64.0 * dt) return hi;
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (time_step_ok(mu, mid, tolerance) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

const char* stencil_name(Stencil s) {
  switch (s) {
    case Stencil::exact: return "exact derivative";
    case Stencil::second_order_upwind: return "second-order upwind";
    case Stencil::central: return "central";
    case Stencil::first_order_upwind: return "first-order upwind";
  }
  return "?";
}

RealMatrix16 equilibrium_jacobian(const VelocityModel& model, const MomentInversion& inversion,
                                  const Macro& s, double b) {
  // ∂M^eq/∂(ρ, u_x, u_y, T) by complex step: M^eq is a polynomial, so Im M^eq(x + ih e_q)/h is
  // its derivative to round-off for any small h.
  constexpr double h = 1e-30;
  Eigen::Matrix<double, kMoments, 4> dm;
  for (int q = 0; q < 4; ++q) {
    Complex x[4] = {s.rho, s.ux, s.uy, s.T};
    x[q] += Complex(0.0, h);
    put_equilibrium_moments(x[0], x[1], x[2], x[3], b,
                            [&](int m, Complex value) { dm(m, q) = value.imag() / h; });
  }
  // C⁻¹ ∂M^eq/∂(ρ, u, T): ∂f^eq/∂(ρ, u, T).
  Eigen::Matrix<double, kMoments, 4> df;
  for (int q = 0; q < 4; ++q) {
    const Eigen::Matrix<double, kMoments, 1> column = dm.col(q);
    inversion.distribution(column, df.col(q).data());
  }
  // ∂(ρ, u, T)/∂(ρ, ρu, E) from u = ρu/ρ, T = (2E/ρ − u²)/b (eqs. 20–22).
  const double r = s.rho, u2 = s.ux * s.ux + s.uy * s.uy;
  Eigen::Matrix4d primitive;
  primitive << 1.0, 0.0, 0.0, 0.0,  //
      -s.ux / r, 1.0 / r, 0.0, 0.0,  //
      -s.uy / r, 0.0, 1.0 / r, 0.0,  //
      (u2 - b * s.T) / (b * r), -2.0 * s.ux / (b * r), -2.0 * s.uy / (b * r), 2.0 / (b * r);
  // W: ρ, ρu, E as sums over f (the first four rows of the moment matrix C).
  Eigen::Matrix<double, 4, kMoments> w;
  for (int k = 0; k < kMoments; ++k)
    w.col(k) = moment_row(model.vx[k], model.vy[k], model.eta[k]).head<4>();
  return df * primitive * w;
}

RealMatrix16 collision_jacobian(const StabilityProblem& p, const Macro& state) {
  const MomentInversion inversion(p.model);
  return -(RealMatrix16::Identity() - equilibrium_jacobian(p.model, inversion, state, p.b)) / p.tau;
}

std::complex<double> convection_symbol(double v, double theta, double h, Stencil stencil) {
  // Upwind stencils are written for v > 0 (cells i, i−1, i−2); v < 0 mirrors them (θ → −θ,
  // sign flipped). ∂f/∂x·h of e^{iθi}: second-order upwind (3 − 4e^{−iθ} + e^{−2iθ})/2 (the NND
  // face value f_i + (f_i − f_{i−1})/2), central i sin θ, first-order upwind 1 − e^{−iθ}.
  if (v == 0.0) return 0.0;
  const double t = v > 0.0 ? theta : -theta, sign = v > 0.0 ? 1.0 : -1.0;
  const Complex e = std::polar(1.0, -t);  // e^{−iθ} on the upwind side
  Complex d;
  switch (stencil) {
    case Stencil::exact: d = Complex(0.0, t); break;
    case Stencil::second_order_upwind: d = 0.5 * (3.0 - 4.0 * e + e * e); break;
    case Stencil::central: d = Complex(0.0, std::sin(t)); break;
    case Stencil::first_order_upwind: d = 1.0 - e; break;
  }
  return sign * v * d / h;
}

ComplexMatrix16 step_matrix(const StabilityProblem& p, const RealMatrix16& collision,
                            double theta_x, double theta_y, Stencil stencil) {
  return p.dt * generator(p, collision, theta_x, theta_y, stencil);
}

StabilityReport analyse_stability(const StabilityProblem& p, const Macro& state) {
  const RealMatrix16 J = collision_jacobian(p, state);
  StabilityReport r;
  // The model: |k|τ log-spaced over [1e-3, 1e4] (along an axis the supremum is approached as
  // |k| → ∞, docs/theory/dbm.md), directions aπ/16 in [0, π) (one cell high: along x only);
  // the exact symbol with Δx = τ takes θ = kτ.
  StabilityProblem unit = p;
  unit.dx = unit.dy = p.tau;
  r.model_rate = -INFINITY;
  for (int a = 0; a < (p.two_dimensional ? 16 : 1); ++a)
    for (double kt = 1e-3; kt < 1.0001e4; kt *= 1.1) {
      const double angle = std::numbers::pi * a / 16;
      for (const Complex m : eigenvalues(generator(unit, J, kt * std::cos(angle), kt * std::sin(angle),
                                                   Stencil::exact)))
        if (m.real() > r.model_rate) r.model_rate = m.real(), r.model_k_tau = kt, r.model_angle = angle;
    }
  // The discretised model on the lattice's wave vectors.
  const std::vector<double> theta_y =
      p.two_dimensional ? wave_numbers(p.resolution, true) : std::vector<double>{0.0};
  std::vector<Complex> mu;  // eigenvalues of the generator at every wave vector
  r.semi_discrete_rate = -INFINITY;
  for (double ty : theta_y)
    for (double tx : wave_numbers(p.resolution, false))
      for (const Complex m : eigenvalues(generator(p, J, tx, ty, p.stencil))) {
        mu.push_back(m);
        if (m.real() > r.semi_discrete_rate) r.semi_discrete_rate = m.real(), r.theta_x = tx, r.theta_y = ty;
        r.amplification = std::max(r.amplification, std::abs(rk3_factor(p.dt * m)));
      }
  r.discrete_rate = std::log(r.amplification) / p.dt;
  r.stable_dt = largest_stable_dt(mu, p.dt, tolerance_rate(p.tau));
  if (p.stencil != Stencil::first_order_upwind) return r;
  // The smooth modes with the stencil NND has there, on a grid as fine as the full one's.
  const std::vector<double> smooth_y =
      p.two_dimensional ? wave_numbers(p.resolution, true, kSmoothTheta) : std::vector<double>{0.0};
  r.smooth_rate = -INFINITY;
  for (double ty : smooth_y)
    for (double tx : wave_numbers(p.resolution, false, kSmoothTheta))
      for (const Complex m : eigenvalues(generator(p, J, tx, ty, Stencil::second_order_upwind))) {
        const double rate = std::log(std::abs(rk3_factor(p.dt * m))) / p.dt;
        if (rate > r.smooth_rate) r.smooth_rate = rate, r.smooth_theta_x = tx, r.smooth_theta_y = ty;
      }
  return r;
}

TemperatureWindow stable_temperatures(const StabilityProblem& p, double T0, bool discrete) {
  const auto stable = [&](double T) {
    const StabilityReport r = analyse_stability(p, {1.0, 0.0, 0.0, T});
    return (discrete ? r.discrete_rate : r.model_rate) <= tolerance_rate(p.tau);
  };
  if (!stable(T0)) return {T0, T0};
  // Bisection in ln T between the stable T0 and the first unstable T of a factor-2 march.
  const auto edge = [&](double factor) {
    double inside = T0, outside = T0 * factor;
    while (stable(outside)) {
      inside = outside, outside *= factor;
      if (outside > 1e3 * T0 || outside < 1e-3 * T0) return inside;
    }
    while (std::abs(std::log(outside / inside)) > 1e-4) {
      const double mid = std::sqrt(inside * outside);
      (stable(mid) ? inside : outside) = mid;
    }
    return inside;
  };
  return {edge(0.5), edge(2.0)};
}

}  // namespace shockfield::dbm
