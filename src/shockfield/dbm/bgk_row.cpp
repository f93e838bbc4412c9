#include "shockfield/dbm/bgk_row.hpp"

#include <algorithm>

#include "shockfield/dbm/convection.hpp"

namespace shockfield::dbm {
namespace {

int sign_of(double v) {
  return (v > 0.0) - (v < 0.0);
}

/// L = −v_x ∂f/∂x − v_y ∂f/∂y − (f − f^eq)/τ over n cells, NND upwinded on the signs Sx, Sy;
/// slope_x (n + 2 entries, from cell −1) holds the limited x slopes of the cells.
template <int Sx, int Sy>
void nnd_bgk(const double* f, const double* eq, const double* slope_x, double* L, int n,
             std::ptrdiff_t sy, double vx_dx, double vy_dy, double inv_tau) {
  for (int i = 0; i < n; ++i)
    L[i] = -(vx_dx * nnd_difference<Sx>(f + i, 1, slope_x + i + 1, 1) +
             vy_dy * nnd_difference<Sy>(f + i, sy)) -
           (f[i] - eq[i]) * inv_tau;
}

template <int Sx>
void nnd_bgk(int sign_y, const double* f, const double* eq, double* slope_x, double* L, int n,
             std::ptrdiff_t sy, double vx_dx, double vy_dy, double inv_tau) {
  if constexpr (Sx != 0)
    for (int i = -1; i <= n; ++i) slope_x[i + 1] = limited_slope(f + i, 1);
  if (sign_y > 0) return nnd_bgk<Sx, 1>(f, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau);
  if (sign_y < 0) return nnd_bgk<Sx, -1>(f, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau);
  nnd_bgk<Sx, 0>(f, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau);
}

}  // namespace

BgkRow::BgkRow(const VelocityModel& model, const MomentInversion& inversion, const Lattice& lattice,
               double b, double tau)
    : model_(model),
      inversion_(inversion),
      lattice_(lattice),
      b_(b),
      inv_tau_(1.0 / tau),
      rho_(chunk),
      ux_(chunk),
      uy_(chunk),
      T_(chunk),
      work_(2 * kMoments * chunk),
      eq_(static_cast<std::size_t>(model.size()) * chunk),
      rhs_(chunk),
      slope_x_(chunk + 2) {}

void BgkRow::equilibrium_chunk(const double* f, std::size_t c0, int n) {
  // Eqs. 20–22, summed over k in the same order as macro_of() (bit-identical).
  const std::size_t N = lattice_.cells();
  std::fill_n(rho_.begin(), n, 0.0);
  std::fill_n(ux_.begin(), n, 0.0);
  std::fill_n(uy_.begin(), n, 0.0);
  std::fill_n(T_.begin(), n, 0.0);
  for (int k = 0; k < model_.size(); ++k) {
    const double* fk = f + k * N + c0;
    const double vx = model_.vx[k], vy = model_.vy[k];
    const double w = 0.5 * (vx * vx + vy * vy + model_.eta[k] * model_.eta[k]);
    for (int i = 0; i < n; ++i) {
      rho_[i] += fk[i];
      ux_[i] += fk[i] * vx;
      uy_[i] += fk[i] * vy;
      T_[i] += fk[i] * w;
    }
  }
  for (int i = 0; i < n; ++i) {
    const Macro m = macro_from_sums(rho_[i], ux_[i], uy_[i], T_[i], b_);
    ux_[i] = m.ux, uy_[i] = m.uy, T_[i] = m.T;
  }
  inversion_.equilibria(rho_.data(), ux_.data(), uy_.data(), T_.data(), n, b_, eq_.data(),
                        work_.data());
}

void BgkRow::rhs(const double* f, int j, int chunk_index, const double* convection,
                 const RowOutput& output) {
  const std::size_t N = lattice_.cells();
  const auto sy = static_cast<std::ptrdiff_t>(lattice_.stride());
  const int nx = lattice_.nx;
  const int i0 = chunk_index * chunk, n = std::min(chunk, nx - i0);
  const std::size_t c0 = lattice_.at(i0, j);
  double* L = rhs_.data();
  double* slope_x = slope_x_.data();
  equilibrium_chunk(f, c0, n);
  for (int k = 0; k < model_.size(); ++k) {
    const double* fk = f + k * N + c0;
    const double* eq = eq_.data() + static_cast<std::size_t>(k) * n;
    if (convection) {
      const double* c = convection + (static_cast<std::size_t>(k) * lattice_.ny + j) * nx + i0;
      for (int i = 0; i < n; ++i) L[i] = -c[i] - (fk[i] - eq[i]) * inv_tau_;
    } else {
      const double vx_dx = model_.vx[k] / lattice_.dx, vy_dy = model_.vy[k] / lattice_.dy;
      const int sign_y = sign_of(model_.vy[k]);
      if (model_.vx[k] > 0.0)
        nnd_bgk<1>(sign_y, fk, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau_);
      else if (model_.vx[k] < 0.0)
        nnd_bgk<-1>(sign_y, fk, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau_);
      else
        nnd_bgk<0>(sign_y, fk, eq, slope_x, L, n, sy, vx_dx, vy_dy, inv_tau_);
    }
    double* o = output.out + k * N + c0;
    if (!output.base) {
      std::copy_n(L, n, o);
      continue;
    }
    const double* base = output.base + k * N + c0;
    const double a = output.a, dt = output.dt;
    for (int i = 0; i < n; ++i) o[i] = runge_kutta_stage(a, base[i], fk[i], dt, L[i]);
  }
}

}  // namespace shockfield::dbm
