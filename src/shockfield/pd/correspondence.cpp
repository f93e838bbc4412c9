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
  // A checkpoint stores each state field as one array over the points (saved_state), so every
  // point's material must save the same layout (one crystal type, as many grains everywhere).
  const StateLayout layout = materials_.front().state_layout();
  for (const Material& m : materials_)
    if (m.state_layout().size() != layout.size() || m.state_layout().grains != layout.grains)
      throw InputError("pd correspondence: the points' materials hold states of different layouts (grains or slip "
                       "systems per point differ), which a checkpoint cannot store as one array per quantity");
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

namespace {

// Where field k of grain g starts in a point's save() block, and the array's values per point.
std::size_t field_offset(const StateLayout& layout, std::size_t k, std::size_t g) {
  std::size_t at = g * layout.grain_size();
  for (std::size_t f = 0; f < k; ++f) at += layout.fields[f].count;
  return at;
}
std::vector<std::size_t> field_shape(const StateLayout& layout, const StateField& f) {
  std::vector<std::size_t> shape;
  if (layout.per_grain) shape.push_back(layout.grains);
  if (f.count > 1) shape.push_back(f.count);
  return shape;
}

}  // namespace

template <CorrespondenceMaterial Material>
ModelState CorrespondenceForce<Material>::saved_state() const {
  const std::size_t n = cloud_.size();
  const StateLayout layout = material(0).state_layout();
  ModelState out{{"deformation_gradient", "1", n, {9}, false, std::vector<double>(9 * n), {}}};
  for (const StateField& f : layout.fields) {
    ModelStateArray a{f.name, f.units, n, field_shape(layout, f), f.integer, {}, {}};
    (f.integer ? a.counts.resize(n * a.row_size()) : a.reals.resize(n * a.row_size()));
    out.push_back(std::move(a));
  }
  std::vector<double> block(layout.size());
  for (std::size_t i = 0; i < n; ++i) {
    std::copy_n(f_[i].data(), 9, &out[0].reals[9 * i]);
    material(i).save(state_[i], block.data());
    for (std::size_t k = 0; k < layout.fields.size(); ++k) {
      ModelStateArray& a = out[k + 1];
      const std::size_t count = layout.fields[k].count, row = a.row_size();
      for (std::size_t g = 0; g < layout.grains; ++g)
        for (std::size_t c = 0; c < count; ++c) {
          const double v = block[field_offset(layout, k, g) + c];
          const std::size_t at = i * row + g * count + c;
          if (a.integer)
            a.counts[at] = static_cast<std::int64_t>(v);
          else
            a.reals[at] = v;
        }
    }
  }
  return out;
}

template <CorrespondenceMaterial Material>
void CorrespondenceForce<Material>::restore_state(const ModelState& state) {
  const std::size_t n = cloud_.size();
  const StateLayout layout = material(0).state_layout();
  const std::vector<double>& f = saved_array(state, name(), "deformation_gradient", n, 9, false).reals;
  std::vector<const ModelStateArray*> arrays;
  for (const StateField& field : layout.fields)
    arrays.push_back(&saved_array(state, name(), field.name, n, layout.grains * field.count, field.integer));
  std::vector<double> block(layout.size());
  for (std::size_t i = 0; i < n; ++i) {
    f_[i] = Mat3(&f[9 * i]);
    for (std::size_t k = 0; k < layout.fields.size(); ++k) {
      const std::size_t count = layout.fields[k].count, row = layout.grains * count;
      for (std::size_t g = 0; g < layout.grains; ++g)
        for (std::size_t c = 0; c < count; ++c) {
          const std::size_t at = i * row + g * count + c;
          block[field_offset(layout, k, g) + c] =
              arrays[k]->integer ? static_cast<double>(arrays[k]->counts[at]) : arrays[k]->reals[at];
        }
    }
    material(i).load(state_[i], block.data());
  }
}

template class CorrespondenceForce<SmallStrainJ2>;
template class CorrespondenceForce<CrystalMaterial>;

}  // namespace shockfield::pd
