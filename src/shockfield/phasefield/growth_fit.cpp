#include "shockfield/phasefield/growth_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::phasefield {
namespace {

constexpr int kSubsteps = 64;

// y = (R, ∂R/∂R₀, ∂R/∂c₀, ∂R/∂D) of Ṙ = c₀ − kD/R; the sensitivities obey
// ṡ = (kD/R²) s + ∂f/∂p with ∂f/∂c₀ = 1, ∂f/∂D = −k/R.
using State = std::array<double, 4>;
State rate(const State& y, double c0, double D, double k) {
  const double R = y[0], dfdR = k * D / (R * R);
  return {c0 - k * D / R, dfdR * y[1], dfdR * y[2] + 1.0, dfdR * y[3] - k / R};
}

// The law and its Jacobian at every t (rows: R_i, ∂R_i/∂(R₀, c₀, D)).
Eigen::MatrixXd integrate(const std::vector<double>& t, double R0, double c0, double D, int dimensions) {
  const double k = dimensions - 1;
  Eigen::MatrixXd out(static_cast<Eigen::Index>(t.size()), 4);
  State y{R0, 1.0, 0.0, 0.0};
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0) {
      const double h = (t[i] - t[i - 1]) / kSubsteps;
      for (int s = 0; s < kSubsteps && y[0] > 0.0; ++s) {
        auto add = [&](const State& a, const State& b, double f) {
          State r;
          for (int j = 0; j < 4; ++j) r[static_cast<std::size_t>(j)] = a[static_cast<std::size_t>(j)] + f * b[static_cast<std::size_t>(j)];
          return r;
        };
        const State k1 = rate(y, c0, D, k), k2 = rate(add(y, k1, h / 2), c0, D, k);
        const State k3 = rate(add(y, k2, h / 2), c0, D, k), k4 = rate(add(y, k3, h), c0, D, k);
        for (std::size_t j = 0; j < 4; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        if (!(y[0] > 0.0)) y = {0.0, 0.0, 0.0, 0.0};  // the domain vanished
      }
    }
    for (int j = 0; j < 4; ++j) out(static_cast<Eigen::Index>(i), j) = y[static_cast<std::size_t>(j)];
  }
  return out;
}

}  // namespace

std::vector<double> growth_law_radius(const std::vector<double>& t, double R0, double c0, double D, int dimensions) {
  const Eigen::MatrixXd m = integrate(t, R0, c0, D, dimensions);
  return {m.col(0).data(), m.col(0).data() + m.rows()};
}

GrowthFit fit_growth_law(const std::vector<double>& t, const std::vector<double>& R, int dimensions,
                         const std::string& what) {
  const std::size_t m = t.size();
  if (m != R.size()) throw InputError(what + ": as many radii as times expected");
  if (m < 4)
    throw InputError(fmt::format("{}: {} point(s); the growth law Ṙ = c0 - (n-1) D/R has three parameters (R0, c0, D) "
                                 "and needs at least 4 points in time (frames)", what, m));
  for (std::size_t i = 0; i < m; ++i) {
    if (!std::isfinite(t[i]) || !std::isfinite(R[i]) || !(R[i] > 0.0))
      throw InputError(fmt::format("{}: point {} (t = {}, R = {}) is not a finite positive radius", what, i + 1, t[i], R[i]));
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError(fmt::format("{}: the times must increase (point {}: t = {} after {})", what, i + 1, t[i], t[i - 1]));
  }
  GrowthFit fit;
  fit.points = static_cast<int>(m);
  const double k = dimensions - 1;
  // First guess: ΔR/Δt = c₀ − kD ⟨1/R⟩ by least squares over the intervals.
  Eigen::MatrixXd X(static_cast<Eigen::Index>(m - 1), 2);
  Eigen::VectorXd y(static_cast<Eigen::Index>(m - 1));
  for (std::size_t i = 0; i + 1 < m; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    X(r, 0) = 1.0;
    X(r, 1) = -k * 0.5 * (1.0 / R[i] + 1.0 / R[i + 1]);
    y(r) = (R[i + 1] - R[i]) / (t[i + 1] - t[i]);
  }
  const Eigen::Vector2d guess = X.colPivHouseholderQr().solve(y);
  fit.c0_differences = guess(0);
  fit.D_differences = guess(1);
  Eigen::Vector3d p(R[0], guess(0), guess(1));
  const Eigen::Map<const Eigen::VectorXd> data(R.data(), static_cast<Eigen::Index>(m));
  auto chi2 = [&](const Eigen::Vector3d& q) { return (data - integrate(t, q(0), q(1), q(2), dimensions).col(0)).squaredNorm(); };
  double lambda = 1e-3, current = chi2(p);
  Eigen::MatrixXd J;
  for (fit.iterations = 0; fit.iterations < 200; ++fit.iterations) {
    const Eigen::MatrixXd model = integrate(t, p(0), p(1), p(2), dimensions);
    J = model.rightCols(3);
    const Eigen::VectorXd r = data - model.col(0);
    const Eigen::Matrix3d A = J.transpose() * J;
    const Eigen::Vector3d g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::Matrix3d damped = A;
      damped.diagonal() *= 1.0 + lambda;
      const Eigen::Vector3d step = damped.ldlt().solve(g);
      const double next = chi2(p + step);
      if (std::isfinite(next) && next <= current) {
        p += step;
        improved = true;
        lambda = std::max(lambda / 10, 1e-12);
        const double change = current - next;
        current = next;
        if (change <= 1e-14 * std::max(current, 1e-300) || step.norm() < 1e-12 * (1.0 + p.norm())) fit.converged = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) fit.converged = true;  // no step lowers χ²: at the minimum (to round-off)
    if (fit.converged) break;
  }
  J = integrate(t, p(0), p(1), p(2), dimensions).rightCols(3);
  const double s2 = current / static_cast<double>(m - 3);
  const Eigen::Matrix3d C = s2 * (J.transpose() * J).inverse();
  fit.R0 = p(0), fit.c0 = p(1), fit.D = p(2);
  fit.R0_stderr = std::sqrt(C(0, 0)), fit.c0_stderr = std::sqrt(C(1, 1)), fit.D_stderr = std::sqrt(C(2, 2));
  fit.c0_D_covariance = C(1, 2);
  fit.residual_rms = std::sqrt(current / static_cast<double>(m));
  for (double v : {fit.R0, fit.c0, fit.D, fit.R0_stderr, fit.c0_stderr, fit.D_stderr, fit.c0_D_covariance})
    if (!std::isfinite(v))
      throw InputError(fmt::format("{}: the points do not determine R0, c0 and D (the least-squares fit has no finite "
                                   "solution or covariance: R from {} to {} over t from {} to {})",
                                   what, R.front(), R.back(), t.front(), t.back()));
  return fit;
}

}  // namespace shockfield::phasefield
