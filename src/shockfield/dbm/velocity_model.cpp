#include "shockfield/dbm/velocity_model.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/simd_clones.hpp"

namespace shockfield::dbm {

using Moments = Eigen::Matrix<double, kMoments, 1>;
using Matrix = Matrix16;

namespace {

/// R of the factored C⁻¹ (see MomentInversion): when each group of four consecutive velocities
/// holds the rotations by 0, 90, 180, 270° of its first one (same η), row k = 4g + r holds the
/// weights (1, ê_r,x, ê_r,y, (−1)^r) of the modes of group g; otherwise the identity.
Matrix rotation_group_modes(const VelocityModel& model) {
  Matrix R = Matrix::Zero();
  for (int g = 0; g < kMoments / 4; ++g) {
    const int k0 = 4 * g;
    const double speed = std::hypot(model.vx[k0], model.vy[k0]);
    for (int r = 0; r < 4; ++r) {
      const int k = k0 + r;
      // Rotating (vx, vy) by r·90°: (vx, vy) → (−vy, vx) applied r times.
      double ex = model.vx[k0], ey = model.vy[k0];
      for (int q = 0; q < r; ++q) {
        const double x = ex;
        ex = -ey, ey = x;
      }
      const bool rotated = speed > 0.0 && std::abs(model.vx[k] - ex) < 1e-12 * speed &&
                           std::abs(model.vy[k] - ey) < 1e-12 * speed &&
                           model.eta[k] == model.eta[k0];
      if (!rotated) return Matrix::Identity();
      R(k, k0) = 1.0;
      R(k, k0 + 1) = model.vx[k] / speed;
      R(k, k0 + 2) = model.vy[k] / speed;
      R(k, k0 + 3) = r % 2 == 0 ? 1.0 : -1.0;
    }
  }
  return R;
}

}  // namespace

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
  r << 1.0,                                                    // eq. 20
      vx, vy,                                                  // eq. 21
      e,                                                       // eq. 22
      vx * vx, vx * vy, vy * vy,                               // eq. 23
      vx * vx * vx, vx * vx * vy, vx * vy * vy, vy * vy * vy,  // eq. 24
      e * vx, e * vy,                                          // eq. 25
      e * vx * vx, e * vx * vy, e * vy * vy;                   // eq. 26
  return r;
}

Moments equilibrium_moments(double rho, double ux, double uy, double T, double b) {
  Moments m;
  put_equilibrium_moments(rho, ux, uy, T, b, [&](int q, double value) { m(q) = value; });
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
  return macro_from_sums(rho, jx, jy, e, b);
}

MomentInversion::MomentInversion(const VelocityModel& model) {
  if (model.size() != kMoments)
    throw InputError(fmt::format(
        "velocity model {} has {} velocities; the seven moment relations (seed eqs. 20-26) fix "
        "{} moment components, so f^eq = C^-1 M^eq needs exactly {} velocities",
        model.name, model.size(), kMoments, kMoments));
  Matrix C;
  for (int k = 0; k < kMoments; ++k) C.col(k) = moment_row(model.vx[k], model.vy[k], model.eta[k]);
  const Eigen::FullPivLU<Matrix> lu(C);
  // 1-norm condition number ‖C‖₁‖C⁻¹‖₁ (infinite when C is singular).
  condition_ = lu.isInvertible() ? C.cwiseAbs().colwise().sum().maxCoeff() *
                                       lu.inverse().cwiseAbs().colwise().sum().maxCoeff()
                                 : INFINITY;
  if (!(condition_ < 1e12))
    throw InputError(fmt::format(
        "velocity model {} cannot satisfy the seven moment relations (seed eqs. 20-26): its "
        "16x16 moment matrix C is singular (condition number {:.3g}); choose distinct speeds "
        "and a non-zero eta0",
        model.name, condition_));
  const Matrix inverse = lu.inverse();
  const Matrix R = rotation_group_modes(model);
  const Matrix S = R.fullPivLu().solve(inverse);
  // Entries zero by symmetry come out at round-off; keep the rest and check the product.
  const double cutoff = 1e-13 * S.cwiseAbs().maxCoeff();
  Matrix kept = Matrix::Zero();
  for (int row = 0; row < kMoments; ++row)
    for (int m = 0; m < kMoments; ++m)
      if (std::abs(S(row, m)) > cutoff) {
        modes_.push_back({row, m, S(row, m)});
        kept(row, m) = S(row, m);
      }
  for (int k = 0; k < kMoments; ++k)
    for (int q = 0; q < kMoments; ++q)
      if (R(k, q) != 0.0) rebuild_.push_back({k, q, R(k, q)});
  const double error = (R * kept - inverse).cwiseAbs().maxCoeff() / inverse.cwiseAbs().maxCoeff();
  if (!(error < 1e-12))
    throw RunError(
        fmt::format("velocity model {}: factored C^-1 is off by {:.3g}", model.name, error));
  groups_ = group_weights(R, S, inverse);
}

std::vector<MomentInversion::GroupWeights> MomentInversion::group_weights(const Matrix& R,
                                                                          const Matrix& S,
                                                                          const Matrix& inverse) {
  if (R.isIdentity()) return {};
  std::vector<GroupWeights> groups(kMoments / 4);
  Matrix S_form = Matrix::Zero(), R_form = Matrix::Zero();
  for (int g = 0; g < kMoments / 4; ++g) {
    const int a = 4 * g, bx = a + 1, by = a + 2, d = a + 3;
    GroupWeights& w = groups[g];
    w = {{S(a, 0), S(a, 3), S(a, 4), S(a, 13)},
         {S(bx, 1), S(bx, 7), S(bx, 9), S(bx, 11)},
         {S(d, 4), S(d, 13), S(d, 5), S(d, 14)},
         R(a, a + 1),
         R(a, a + 2)};
    S_form(a, 0) = w.a[0], S_form(a, 3) = w.a[1];
    S_form(a, 4) = S_form(a, 6) = w.a[2], S_form(a, 13) = S_form(a, 15) = w.a[3];
    S_form(bx, 1) = S_form(by, 2) = w.b[0], S_form(bx, 7) = S_form(by, 10) = w.b[1];
    S_form(bx, 9) = S_form(by, 8) = w.b[2], S_form(bx, 11) = S_form(by, 12) = w.b[3];
    S_form(d, 4) = w.d[0], S_form(d, 6) = -w.d[0], S_form(d, 13) = w.d[1];
    S_form(d, 15) = -w.d[1], S_form(d, 5) = w.d[2], S_form(d, 14) = w.d[3];
    // Velocity r of the group: ê rotated by r·90°, (ex, ey) → (−ey, ex).
    double ex = w.ex, ey = w.ey;
    for (int r = 0; r < 4; ++r) {
      R_form(a + r, a) = 1.0, R_form(a + r, bx) = ex, R_form(a + r, by) = ey;
      R_form(a + r, d) = r % 2 == 0 ? 1.0 : -1.0;
      const double x = ex;
      ex = -ey, ey = x;
    }
  }
  const double error =
      (R_form * S_form - inverse).cwiseAbs().maxCoeff() / inverse.cwiseAbs().maxCoeff();
  if (!(error < 1e-12)) return {};
  return groups;
}

void MomentInversion::apply(const std::vector<Term>& terms, const double* in, int n, double* out) {
  std::fill(out, out + static_cast<std::size_t>(kMoments) * n, 0.0);
  for (const Term& t : terms) {
    double* o = out + static_cast<std::size_t>(t.row) * n;
    const double* x = in + static_cast<std::size_t>(t.column) * n;
    const double w = t.weight;
    for (int i = 0; i < n; ++i) o[i] += w * x[i];
  }
}

SHOCKFIELD_SIMD_CLONES void MomentInversion::equilibria(const double* rho, const double* ux, const double* uy,
                                 const double* T, int n, double b, double* out,
                                 double* work) const {
  if (!groups_.empty()) {
    GroupWeights w[kMoments / 4];
    std::copy(groups_.begin(), groups_.end(), w);
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      double m[kMoments];
      put_equilibrium_moments(rho[i], ux[i], uy[i], T[i], b,
                              [&](int q, double value) { m[q] = value; });
      const double trace2 = m[4] + m[6], diff2 = m[4] - m[6];
      const double trace4 = m[13] + m[15], diff4 = m[13] - m[15];
#pragma GCC unroll 4
      for (int g = 0; g < kMoments / 4; ++g) {
        const GroupWeights& x = w[g];
        const double a = x.a[0] * m[0] + x.a[1] * m[3] + x.a[2] * trace2 + x.a[3] * trace4;
        const double bx = x.b[0] * m[1] + x.b[1] * m[7] + x.b[2] * m[9] + x.b[3] * m[11];
        const double by = x.b[0] * m[2] + x.b[1] * m[10] + x.b[2] * m[8] + x.b[3] * m[12];
        const double d = x.d[0] * diff2 + x.d[1] * diff4 + x.d[2] * m[5] + x.d[3] * m[14];
        // ê·b of velocities 0 and 1 of the group (velocities 2, 3 have −ê).
        const double p = x.ex * bx + x.ey * by, q = x.ex * by - x.ey * bx;
        double* f = out + static_cast<std::size_t>(4 * g) * n + i;
        f[0] = (a + d) + p, f[n] = (a - d) + q, f[2 * n] = (a + d) - p, f[3 * n] = (a - d) - q;
      }
    }
    return;
  }
  double* moments = work;
  double* modes = work + static_cast<std::size_t>(kMoments) * n;
#pragma omp simd
  for (int i = 0; i < n; ++i)
    put_equilibrium_moments(rho[i], ux[i], uy[i], T[i], b,
                            [&](int m, double value) { moments[m * n + i] = value; });
  apply(modes_, moments, n, modes);
  apply(rebuild_, modes, n, out);
}

void MomentInversion::equilibrium(double rho, double ux, double uy, double T, double b,
                                  double* out) const {
  double work[2 * kMoments];
  equilibria(&rho, &ux, &uy, &T, 1, b, out, work);
}

void MomentInversion::distribution(const Moments& moments, double* out) const {
  double modes[kMoments];
  apply(modes_, moments.data(), 1, modes);
  apply(rebuild_, modes, 1, out);
}

}  // namespace shockfield::dbm
