#include "shockfield/pd/correspondence.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"
#include "shockfield/pd/crystal_material.hpp"
#include "shockfield/pd/riemann.hpp"

namespace shockfield::pd {

template <CorrespondenceMaterial Material>
CorrespondenceForce<Material>::CorrespondenceForce(const PointCloud& cloud, const Family& family,
                                                   std::vector<Material> materials, Influence influence,
                                                   CorrespondenceOptions options)
    : cloud_(cloud), family_(family), materials_(std::move(materials)), options_(options) {
  const std::size_t n = cloud.size();
  if (materials_.size() != 1 && materials_.size() != n)
    throw InputError(fmt::format("pd correspondence: {} materials for {} points", materials_.size(), n));
  unused_ = Mat3::Zero();
  for (int d = cloud.dim; d < 3; ++d) unused_(d, d) = 1.0;
  omega_.resize(family.bonds());
  k_inv_.resize(n);
  weighted_volume_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    Mat3 k = Mat3::Zero();  // eq. 7
    for (int b = family.begin(i); b < family.end(i); ++b) {
      const int j = family.neighbor[b];
      const Vec3 xi = cloud.x[j] - cloud.x[i];
      omega_[b] = influence(family.length[b], family.horizon);
      const double w = omega_[b] * family.volume_scale[b] * cloud.volume[j];
      k += w * xi * xi.transpose();
      weighted_volume_[i] += w * xi.squaredNorm();
    }
    // Singular when the neighbours do not span the body's dimension (relative to the largest
    // eigenvalue, so the check is independent of units).
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(k);
    const auto ev = eig.eigenvalues();
    const double smallest = ev[3 - cloud.dim], largest = ev[2];
    if (!(largest > 0.0) || smallest < 1e-10 * largest)
      throw InputError(fmt::format(
          "pd correspondence: the shape tensor K of point {} at ({:.6g}, {:.6g}, {:.6g}) m is singular ({} neighbours "
          "within δ = {:.6g} m do not span {} dimensions); enlarge the horizon or remove the isolated point",
          i, cloud.x[i][0], cloud.x[i][1], cloud.x[i][2], family.end(i) - family.begin(i), family.horizon, cloud.dim));
    k_inv_[i] = (k + unused_).inverse() - unused_;
  }
  f_.assign(n, Mat3::Identity());
  sigma_.assign(n, Mat3::Zero());
  pk_.assign(n, Mat3::Zero());
  ak_.assign(n, Mat3::Zero());
  sigma_m_.assign(n, 0.0);
  rho_.assign(n, 0.0);
  state_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) state_.push_back(material(i).initial_state());
}

template <CorrespondenceMaterial Material>
void CorrespondenceForce<Material>::compute(const Kinematics& k, std::vector<Vec3>& force_density) {
  const auto n = static_cast<std::ptrdiff_t>(cloud_.size());
  const auto& y = k.y;
  // Points: F (eq. 8), the constitutive update, P = A σ (eq. 10) and the products with K⁻¹.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t si = 0; si < n; ++si) {
    const auto i = static_cast<std::size_t>(si);
    Mat3 sum = Mat3::Zero();
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      const int j = family_.neighbor[b];
      sum += (omega_[b] * family_.volume_scale[b] * cloud_.volume[j]) * (y[j] - y[i]) * (cloud_.x[j] - cloud_.x[i]).transpose();
    }
    const Mat3 f_new = sum * k_inv_[i] + unused_;
    const Material& m = material(i);
    sigma_[i] = m.update(state_[i], f_[i], f_new, k.dt);
    f_[i] = f_new;
    const double jac = m.finite_strain() ? f_new.determinant() : 1.0;
    const Mat3 a = m.finite_strain() ? Mat3(jac * f_new.inverse().transpose()) : Mat3::Identity();
    pk_[i] = a * sigma_[i] * k_inv_[i];
    ak_[i] = a * k_inv_[i];
    sigma_m_[i] = sigma_[i].trace() / 3.0;
    rho_[i] = m.reference_density() / jac;
  }
  // Bonds: T̂ of eq. 11, or eqs. 13 + 16 with the interface pressure, plus the mode penalty.
  force_density.resize(cloud_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t si = 0; si < n; ++si) {
    const auto i = static_cast<std::size_t>(si);
    const Material& mi = material(i);
    const double hg_i = options_.hourglass * mi.longitudinal_modulus() / weighted_volume_[i];
    Vec3 f = Vec3::Zero();
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      const auto j = static_cast<std::size_t>(family_.neighbor[b]);
      const Vec3 xi = cloud_.x[j] - cloud_.x[i];
      const Vec3 bond = y[j] - y[i];
      Vec3 t;
      if (options_.riemann) {
        const Material& mj = material(j);
        const double r = bond.norm();
        const Vec3 e = r > 0.0 ? Vec3(bond / r) : Vec3(xi.normalized());
        const auto side = [&](std::size_t p, const Material& m) {
          return RiemannSide{-sigma_m_[p], k.v[p].dot(e), rho_[p], std::sqrt(m.longitudinal_modulus() / rho_[p]),
                             m.hugoniot_slope()};
        };
        const double sigma_star = -dukowicz_two_shock(side(i, mi), side(j, mj)).p;  // eq. 15
        t = (pk_[i] - sigma_m_[i] * ak_[i] + pk_[j] - sigma_m_[j] * ak_[j]) * xi  // eq. 13
            + sigma_star * ((ak_[i] + ak_[j]) * xi);                             // eq. 16
      } else {
        t = (pk_[i] + pk_[j]) * xi;  // eq. 11
      }
      t *= omega_[b];
      if (options_.hourglass != 0.0) {
        const double hg_j = options_.hourglass * material(j).longitudinal_modulus() / weighted_volume_[j];
        t += omega_[b] * (hg_i * (bond - f_[i] * xi) + hg_j * (bond - f_[j] * xi));
      }
      f += (family_.volume_scale[b] * cloud_.volume[j]) * t;
    }
    force_density[i] = f;
  }
}

template <CorrespondenceMaterial Material>
double CorrespondenceForce<Material>::stable_step(const std::vector<double>& density) const {
  // Gershgorin bound of the linearised operator: with g_i = Σ_j ω β V_j |K_i⁻¹ξ|, the row sums of
  // ∂L/∂u are at most 4·M·g² (F depends on u with weights bounded by g, T̂ on F with the same),
  // plus the penalty's 2·Σ_j ω β V_j (k_i + k_j); Δt = 2√(ρ / row sum).
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    double g = 0.0, hg = 0.0;
    const double ki = options_.hourglass * material(i).longitudinal_modulus() / weighted_volume_[i];
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      const int j = family_.neighbor[b];
      const double w = omega_[b] * family_.volume_scale[b] * cloud_.volume[j];
      g += w * (k_inv_[i] * (cloud_.x[j] - cloud_.x[i])).norm();
      hg += 2.0 * w * (ki + options_.hourglass * material(j).longitudinal_modulus() / weighted_volume_[j]);
    }
    const double row = 4.0 * material(i).longitudinal_modulus() * g * g + hg;
    dt = std::min(dt, 2.0 * std::sqrt(density[i] / row));
  }
  return dt;
}

template <CorrespondenceMaterial Material>
std::vector<double> CorrespondenceForce<Material>::saved_state() const {
  std::vector<double> out;
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    const std::size_t at = out.size();
    out.resize(at + 9 + material(i).state_size());
    std::copy_n(f_[i].data(), 9, &out[at]);
    material(i).save(state_[i], &out[at + 9]);
  }
  return out;
}

template <CorrespondenceMaterial Material>
void CorrespondenceForce<Material>::restore_state(const std::vector<double>& data) {
  std::size_t expected = 0;
  for (std::size_t i = 0; i < cloud_.size(); ++i) expected += 9 + material(i).state_size();
  if (data.size() != expected)
    throw InputError(fmt::format("pd correspondence: saved state of {} values, expected {} for {} points", data.size(),
                                 expected, cloud_.size()));
  for (std::size_t i = 0, at = 0; i < cloud_.size(); at += 9 + material(i).state_size(), ++i) {
    f_[i] = Mat3(&data[at]);
    material(i).load(state_[i], &data[at + 9]);
  }
}

template class CorrespondenceForce<SmallStrainJ2>;
template class CorrespondenceForce<CrystalMaterial>;

}  // namespace shockfield::pd
