#include "shockfield/dbm/bgk_row.hpp"

#include <algorithm>
#include <type_traits>

#include "shockfield/core/simd_clones.hpp"
#include "shockfield/dbm/convection.hpp"

namespace shockfield::dbm {
namespace {

template <int S>
using Sign = std::integral_constant<int, S>;

/// Calls body(Sign<±1 or 0>) for the sign of v, so that the upwind side is a compile-time
/// constant in the loops over cells.
template <class Body>
void with_sign(double v, Body&& body) {
  if (v > 0.0)
    body(Sign<1>{});
  else if (v < 0.0)
    body(Sign<-1>{});
  else
    body(Sign<0>{});
}

/// The y face values a row kernel starts from at row j (p: f at cell (i0, j) of one velocity):
/// those of row j − 1 for an upwind sign Sy > 0, of row j for Sy < 0.
template <int Sy>
void start_faces_y(const double* p, double* face_y, int n, std::ptrdiff_t sy) {
  if constexpr (Sy != 0) {
    const double* row = p + (Sy > 0 ? -sy : 0);
#pragma omp simd
    for (int i = 0; i < n; ++i) face_y[i] = downwind_face<Sy>(row + i, sy);
  }
}

/// L = −(v_x/Δx · h∂f/∂x + v_y/Δy · h∂f/∂y) − (f − f^eq)/τ of one velocity over n cells, NND
/// upwinded on the signs Sx, Sy, handed to emit(i, L). p is f at the first cell; face_x (n + 2
/// entries from cell −1) receives the x face values of the row; face_y holds the y face values
/// of the previous row (start_faces_y) and receives those of this one.
template <int Sx, int Sy, class Emit>
void nnd_bgk(const double* p, const double* eq, double* face_x, double* face_y, int n,
             std::ptrdiff_t sy, double vx_dx, double vy_dy, double inv_tau, Emit&& emit) {
  if constexpr (Sx != 0) {
#pragma omp simd
    for (int i = -1; i <= n; ++i) face_x[i + 1] = downwind_face<Sx>(p + i, 1);
  }
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    double dx = 0.0, dy = 0.0;
    if constexpr (Sx > 0) dx = face_x[i + 1] - face_x[i];
    if constexpr (Sx < 0) dx = face_x[i + 2] - face_x[i + 1];
    if constexpr (Sy != 0) {
      const double face = downwind_face<Sy>(p + i + (Sy < 0 ? sy : 0), sy);
      dy = face - face_y[i];
      face_y[i] = face;
    }
    emit(i, -(vx_dx * dx + vy_dy * dy) - (p[i] - eq[i]) * inv_tau);
  }
}

}  // namespace

SHOCKFIELD_SIMD_CLONES void runge_kutta_row(double a, const double* base, const double* f,
                                            double dt, const double* L, int n, double* out) {
#pragma omp simd
  for (int i = 0; i < n; ++i) out[i] = runge_kutta_stage(a, base[i], f[i], dt, L[i]);
}

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
      eq_(static_cast<std::size_t>(kMoments) * chunk),
      face_x_(chunk + 2),
      face_y_(static_cast<std::size_t>(kMoments) * chunk) {}

void BgkRow::prefetch_next_row(const double* f, int k, int j, int i0, int n,
                               const RowOutput& output) const {
  // Row j first reads f of row j + 2 (cells −2..n+1, the y faces of upwind sign −1) and the
  // rows j of base and out. A row of a chunk is too short a stream for the hardware prefetchers.
  const std::size_t at = k * lattice_.cells() + lattice_.at(i0, j);
  const double* next = f + at + 2 * lattice_.stride();
  for (int i = -2; i < n + 2; i += 8) __builtin_prefetch(next + i, 0, 2);
  __builtin_prefetch(next + n + 1, 0, 2);
  for (int i = 0; i < n; i += 8) {
    if (output.base) __builtin_prefetch(output.base + at + i, 0, 2);
    __builtin_prefetch(output.out + at + i, 1, 2);
  }
  if (output.base) __builtin_prefetch(output.base + at + n - 1, 0, 2);
  __builtin_prefetch(output.out + at + n - 1, 1, 2);
}

SHOCKFIELD_SIMD_CLONES void BgkRow::equilibrium_chunk(const double* f, std::size_t c0, int n) {
  // Eqs. 20–22 per cell, summed over k in the same order as macro_of(); MomentInversion checked
  // that the model has kMoments velocities.
  const std::size_t N = lattice_.cells();
  double vx[kMoments], vy[kMoments], w[kMoments];
  for (int k = 0; k < kMoments; ++k) {
    vx[k] = model_.vx[k], vy[k] = model_.vy[k];
    w[k] = 0.5 * (vx[k] * vx[k] + vy[k] * vy[k] + model_.eta[k] * model_.eta[k]);
  }
  double *rho = rho_.data(), *ux = ux_.data(), *uy = uy_.data(), *T = T_.data();
  const double b = b_;
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    double sum = 0.0, jx = 0.0, jy = 0.0, e = 0.0;
    for (int k = 0; k < kMoments; ++k) {
      const double fk = f[k * N + c0 + i];
      sum += fk;
      jx += fk * vx[k];
      jy += fk * vy[k];
      e += fk * w[k];
    }
    const Macro m = macro_from_sums(sum, jx, jy, e, b);
    rho[i] = sum, ux[i] = m.ux, uy[i] = m.uy, T[i] = m.T;
  }
  inversion_.equilibria(rho, ux, uy, T, n, b_, eq_.data(), work_.data());
}

void BgkRow::rhs(const double* f, int block_index, int chunk_index, const double* convection,
                 const RowOutput& output) {
  const std::size_t N = lattice_.cells();
  const auto sy = static_cast<std::ptrdiff_t>(lattice_.stride());
  const int i0 = chunk_index * chunk, n = std::min(chunk, lattice_.nx - i0);
  const int j0 = block_index * block_rows, j1 = std::min(j0 + block_rows, lattice_.ny);
  if (!convection)
    for (int k = 0; k < kMoments; ++k)
      with_sign(model_.vy[k], [&](auto Sy) {
        start_faces_y<Sy()>(f + k * N + lattice_.at(i0, j0), face_y_.data() + k * chunk, n, sy);
      });
  for (int j = j0; j < j1; ++j) rhs_row(f, j, i0, n, convection, output);
}

SHOCKFIELD_SIMD_CLONES [[gnu::flatten]] void BgkRow::rhs_row(const double* f, int j, int i0, int n, const double* convection,
                     const RowOutput& output) {
  const std::size_t N = lattice_.cells();
  const auto sy = static_cast<std::ptrdiff_t>(lattice_.stride());
  const std::size_t c0 = lattice_.at(i0, j);
  const double inv_tau = inv_tau_;
  equilibrium_chunk(f, c0, n);
  for (int k = 0; k < kMoments; ++k) {
    if (j + 1 < lattice_.ny) prefetch_next_row(f, k, j + 1, i0, n, output);
    const double* p = f + k * N + c0;
    const double* eq = eq_.data() + static_cast<std::size_t>(k) * n;
    double* o = output.out + k * N + c0;
    auto compute = [&](auto&& emit) {
      if (convection) {
        const double* c =
            convection + (static_cast<std::size_t>(k) * lattice_.ny + j) * lattice_.nx + i0;
#pragma omp simd
        for (int i = 0; i < n; ++i) emit(i, -c[i] - (p[i] - eq[i]) * inv_tau);
        return;
      }
      const double vx_dx = model_.vx[k] / lattice_.dx, vy_dy = model_.vy[k] / lattice_.dy;
      double* face_y = face_y_.data() + k * chunk;
      with_sign(model_.vx[k], [&](auto Sx) {
        with_sign(model_.vy[k], [&](auto Sy) {
          nnd_bgk<Sx(), Sy()>(p, eq, face_x_.data(), face_y, n, sy, vx_dx, vy_dy, inv_tau, emit);
        });
      });
    };
    if (!output.base) {
      compute([o](int i, double L) { o[i] = L; });
    } else {
      const double* base = output.base + k * N + c0;
      const double a = output.a, dt = output.dt;
      compute([=](int i, double L) { o[i] = runge_kutta_stage(a, base[i], p[i], dt, L); });
    }
  }
}

}  // namespace shockfield::dbm
