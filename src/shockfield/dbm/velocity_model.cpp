#include "shockfield/dbm/velocity_model.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {

using Moments = Eigen::Matrix<double, kMoments, 1>;

double VelocityModel::max_speed() const {
  double m = 0.0;
  for (int k = 0; k < size(); ++k) m = std::max(m, std::hypot(vx[k], vy[k]));
  return m;
}

std::vector<int> VelocityModel::mirror(int axis) const {
  std::vector<int> map(size(), -1);
  for (int k = 0; k < size(); ++k) {
    const double mx = axis == 0 ? -vx[k] : vx[k];
    const double my = axis == 1 ? -vy[k] : vy[k];
    for (int j = 0; j < size(); ++j) {
      if (std::abs(vx[j] - mx) < 1e-12 && std::abs(vy[j] - my) < 1e-12 &&
          std::abs(eta[j] - eta[k]) < 1e-12)
        map[k] = j;
    }
    if (map[k] < 0)
      throw InputError(fmt::format(
          "velocity model {}: velocity {} ({}, {}) has no mirror image in {}, so it cannot be "
          "used with a reflecting boundary",
          name, k, vx[k], vy[k], axis == 0 ? "x" : "y"));
  }
  return map;
}

VelocityModel d2v16(const std::array<double, 4>& speeds, double eta0) {
  VelocityModel m;
  m.name = fmt::format("D2V16(v = {}, {}, {}, {}; eta0 = {})", speeds[0], speeds[1], speeds[2],
                       speeds[3], eta0);
  for (int group = 0; group < 4; ++group) {
    const double offset = group % 2 == 0 ? 0.0 : std::numbers::pi / 4;
    for (int i = 0; i < 4; ++i) {
      const double angle = offset + i * std::numbers::pi / 2;
      // Round cos/sin of multiples of π/2 to exact zeros so mirror images match exactly.
      const double c = std::round(std::cos(angle) * 1e12) / 1e12;
      const double s = std::round(std::sin(angle) * 1e12) / 1e12;
      m.vx.push_back(speeds[group] * c);
      m.vy.push_back(speeds[group] * s);
      m.eta.push_back(group == 0 ? eta0 : 0.0);
    }
  }
  return m;
}

Moments moment_row(double vx, double vy, double eta) {
  const double e = 0.5 * (vx * vx + vy * vy + eta * eta);  // (v² + η²)/2
  Moments r;
  r << 1.0,                                               // eq. 20
      vx, vy,                                             // eq. 21
      e,                                                  // eq. 22
      vx * vx, vx * vy, vy * vy,                          // eq. 23
      vx * vx * vx, vx * vx * vy, vx * vy * vy, vy * vy * vy,  // eq. 24
      e * vx, e * vy,                                     // eq. 25
      e * vx * vx, e * vx * vy, e * vy * vy;              // eq. 26
  return r;
}

Moments equilibrium_moments(double rho, double ux, double uy, double T, double b) {
  const double u2 = ux * ux + uy * uy;
  const double h = 0.5 * ((b + 2.0) * T + u2);  // M3,1 / (ρu)
  const double g = 0.5 * ((b + 4.0) * T + u2);  // uu coefficient of M4,2 / ρ
  Moments m;
  m << rho,                                                  // eq. 20
      rho * ux, rho * uy,                                    // eq. 21
      0.5 * rho * (b * T + u2),                              // eq. 22
      rho * (T + ux * ux), rho * ux * uy, rho * (T + uy * uy),  // eq. 23
      rho * (3 * T * ux + ux * ux * ux), rho * (T * uy + ux * ux * uy),
      rho * (T * ux + ux * uy * uy), rho * (3 * T * uy + uy * uy * uy),  // eq. 24
      rho * ux * h, rho * uy * h,                                        // eq. 25
      rho * (h * T + g * ux * ux), rho * g * ux * uy, rho * (h * T + g * uy * uy);  // eq. 26
  return m;
}

Macro macro_of(const VelocityModel& model, const double* f, std::size_t stride, double b) {
  double rho = 0, jx = 0, jy = 0, e = 0;
  for (int k = 0; k < model.size(); ++k) {
    const double fk = f[k * stride];
    rho += fk;
    jx += fk * model.vx[k];
    jy += fk * model.vy[k];
    e += 0.5 * fk *
         (model.vx[k] * model.vx[k] + model.vy[k] * model.vy[k] + model.eta[k] * model.eta[k]);
  }
  Macro m;
  m.rho = rho;
  m.ux = jx / rho;
  m.uy = jy / rho;
  m.T = (2.0 * e / rho - m.ux * m.ux - m.uy * m.uy) / b;
  return m;
}

MomentInversion::MomentInversion(const VelocityModel& model) {
  if (model.size() != kMoments)
    throw InputError(fmt::format(
        "velocity model {} has {} velocities; the seven moment relations (seed eqs. 20-26) fix "
        "{} moment components, so f^eq = C^-1 M^eq needs exactly {} velocities",
        model.name, model.size(), kMoments, kMoments));
  Eigen::Matrix<double, kMoments, kMoments> C;
  for (int k = 0; k < kMoments; ++k) C.col(k) = moment_row(model.vx[k], model.vy[k], model.eta[k]);
  const Eigen::FullPivLU<Eigen::Matrix<double, kMoments, kMoments>> lu(C);
  // 1-norm condition number ‖C‖₁‖C⁻¹‖₁ (infinite when C is singular).
  condition_ = lu.isInvertible()
                   ? C.cwiseAbs().colwise().sum().maxCoeff() *
                         lu.inverse().cwiseAbs().colwise().sum().maxCoeff()
                   : INFINITY;
  if (!(condition_ < 1e12))
    throw InputError(fmt::format(
        "velocity model {} cannot satisfy the seven moment relations (seed eqs. 20-26): its "
        "16x16 moment matrix C is singular (condition number {:.3g}); choose distinct speeds "
        "and a non-zero eta0",
        model.name, condition_));
  inverse_ = lu.inverse();
}

void MomentInversion::equilibrium(double rho, double ux, double uy, double T, double b,
                                  double* out) const {
  Eigen::Map<Moments> result(out);
  result.noalias() = inverse_ * equilibrium_moments(rho, ux, uy, T, b);
}

void MomentInversion::distribution(const Moments& moments, double* out) const {
  Eigen::Map<Moments> result(out);
  result.noalias() = inverse_ * moments;
}

}  // namespace shockfield::dbm
