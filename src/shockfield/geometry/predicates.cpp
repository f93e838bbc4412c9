// Filtered exact predicates. The floating-point stage evaluates each determinant the way Shewchuk
// (1997) does in his stage A (differences first, then 2×2 minors), so his forward error bounds
// apply: |computed − exact| <= c·ε·permanent, ε = 2^−53, with c = 3 + 16ε (orient 2D), 7 + 56ε
// (orient 3D), 10 + 96ε (in-circle), 16 + 224ε (in-sphere); the permanent is the same expression
// with every term made non-negative. Inside the bound, the sign is computed exactly: in fixed-width
// integers when the coordinates span at most 61 bits (predicates_grid.hpp; lattices), else in
// expansions.
#include "shockfield/geometry/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shockfield/geometry/expansion.hpp"
#include "shockfield/geometry/predicates_grid.hpp"

namespace shockfield::geometry {
namespace {

constexpr double kEps = 0x1p-53;

int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

/// Exact differences p_i − q (rows i < M−1, q the last point) and their xy minors, the pieces
/// of every determinant below, evaluated as in the floating-point stage but in expansions.
template <int N, std::size_t M>
struct ExactRows {
  Expansion d[M][N];  // row M−1 stays zero (sized M to keep -Warray-bounds quiet)
  explicit ExactRows(const std::array<const double*, M>& p) {
    for (std::size_t i = 0; i + 1 < M; ++i)
      for (int k = 0; k < N; ++k) d[i][k] = Expansion::difference(p[i][k], p[M - 1][k]);
  }
  Expansion minor(int i, int j) const { return d[i][0] * d[j][1] - d[j][0] * d[i][1]; }
  Expansion lift(int i) const {
    Expansion l;
    for (int k = 0; k < N; ++k) l = l + d[i][k] * d[i][k];
    return l;
  }
  /// det of rows i, j, k (3D): z_i m(j,k) − z_j m(i,k) + z_k m(i,j).
  Expansion det3(int i, int j, int k) const {
    return d[i][2] * minor(j, k) - d[j][2] * minor(i, k) + d[k][2] * minor(i, j);
  }
};

double orient2_fast(const PointRefs<3>& p, double& bound) {
  const double left = (p[0][0] - p[2][0]) * (p[1][1] - p[2][1]);
  const double right = (p[0][1] - p[2][1]) * (p[1][0] - p[2][0]);
  bound = (3.0 + 16.0 * kEps) * kEps * (std::abs(left) + std::abs(right));
  return left - right;
}

double orient3_fast(const PointRefs<4>& p, double& bound) {
  const double* d = p[3];
  const double ax = p[0][0] - d[0], ay = p[0][1] - d[1], az = p[0][2] - d[2];
  const double bx = p[1][0] - d[0], by = p[1][1] - d[1], bz = p[1][2] - d[2];
  const double cx = p[2][0] - d[0], cy = p[2][1] - d[1], cz = p[2][2] - d[2];
  const double bycz = by * cz, bzcy = bz * cy, czay = cz * ay, cyaz = cy * az;
  const double aybz = ay * bz, azby = az * by;
  bound = (7.0 + 56.0 * kEps) * kEps *
          ((std::abs(bycz) + std::abs(bzcy)) * std::abs(ax) +
           (std::abs(czay) + std::abs(cyaz)) * std::abs(bx) +
           (std::abs(aybz) + std::abs(azby)) * std::abs(cx));
  return ax * (bycz - bzcy) + bx * (cyaz - czay) + cx * (aybz - azby);
}

double incircle_fast(const PointRefs<4>& p, double& bound) {
  const double* d = p[3];
  const double ax = p[0][0] - d[0], ay = p[0][1] - d[1];
  const double bx = p[1][0] - d[0], by = p[1][1] - d[1];
  const double cx = p[2][0] - d[0], cy = p[2][1] - d[1];
  const double bxcy = bx * cy, cxby = cx * by, cxay = cx * ay, axcy = ax * cy;
  const double axby = ax * by, bxay = bx * ay;
  const double alift = ax * ax + ay * ay, blift = bx * bx + by * by, clift = cx * cx + cy * cy;
  bound = (10.0 + 96.0 * kEps) * kEps *
          ((std::abs(bxcy) + std::abs(cxby)) * alift + (std::abs(cxay) + std::abs(axcy)) * blift +
           (std::abs(axby) + std::abs(bxay)) * clift);
  return alift * (bxcy - cxby) + blift * (cxay - axcy) + clift * (axby - bxay);
}

double insphere_fast(const PointRefs<5>& p, double& bound) {
  const double* e = p[4];
  double x[4], y[4], z[4], lift[4];
  for (int i = 0; i < 4; ++i) {
    x[i] = p[i][0] - e[0];
    y[i] = p[i][1] - e[1];
    z[i] = p[i][2] - e[2];
    lift[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
  }
  // xy minors m(i,j) = x_i y_j − x_j y_i and their permanents.
  auto minor = [&](int i, int j) { return x[i] * y[j] - x[j] * y[i]; };
  auto minor_abs = [&](int i, int j) { return std::abs(x[i] * y[j]) + std::abs(x[j] * y[i]); };
  // det3(rows i, j, k) = z_i m(j,k) − z_j m(i,k) + z_k m(i,j)
  auto det3 = [&](int i, int j, int k) {
    return z[i] * minor(j, k) - z[j] * minor(i, k) + z[k] * minor(i, j);
  };
  auto det3_abs = [&](int i, int j, int k) {
    return std::abs(z[i]) * minor_abs(j, k) + std::abs(z[j]) * minor_abs(i, k) +
           std::abs(z[k]) * minor_abs(i, j);
  };
  // Cofactor expansion along the lift column: D = −l0 M0 + l1 M1 − l2 M2 + l3 M3.
  const double det = (lift[3] * det3(0, 1, 2) - lift[2] * det3(0, 1, 3)) +
                     (lift[1] * det3(0, 2, 3) - lift[0] * det3(1, 2, 3));
  bound = (16.0 + 224.0 * kEps) * kEps *
          (lift[3] * det3_abs(0, 1, 2) + lift[2] * det3_abs(0, 1, 3) +
           lift[1] * det3_abs(0, 2, 3) + lift[0] * det3_abs(1, 2, 3));
  return det;
}

/// The first M point references of p (repeating the last when p has fewer): lets one expression
/// name the 2D and the 3D evaluation; only the branch of the right dimension is taken.
template <std::size_t M, std::size_t K>
PointRefs<M> first(const std::array<const double*, K>& p) {
  PointRefs<M> r;
  for (std::size_t i = 0; i < M; ++i) r[i] = p[std::min(i, K - 1)];
  return r;
}

}  // namespace

template <int N>
int orient_exact(const PointRefs<N + 1>& p) {
  const ExactRows<N, N + 1> r(p);
  if constexpr (N == 2)
    return r.minor(0, 1).sign();
  else
    return r.det3(0, 1, 2).sign();
}

template <int N>
int in_sphere_exact(const PointRefs<N + 2>& p) {
  const ExactRows<N, N + 2> r(p);
  // Cofactor expansion along the lift column, as in the floating-point stage.
  if constexpr (N == 2)
    return (r.lift(0) * r.minor(1, 2) - r.lift(1) * r.minor(0, 2) + r.lift(2) * r.minor(0, 1))
        .sign();
  else
    return ((r.lift(3) * r.det3(0, 1, 2) - r.lift(2) * r.det3(0, 1, 3)) +
            (r.lift(1) * r.det3(0, 2, 3) - r.lift(0) * r.det3(1, 2, 3)))
        .sign();
}

/// The floating-point value decides when it lies outside its error bound.
inline bool decided(double det, double bound) { return det > bound || -det > bound; }

template <int N>
int orient(const PointRefs<N + 1>& p) {
  double bound = 0.0;
  const double det = N == 2 ? orient2_fast(first<3>(p), bound) : orient3_fast(first<4>(p), bound);
  if (decided(det, bound)) return sign_of(det);
  const int on_grid = grid::orient<N>(p);
  return on_grid != 2 ? on_grid : orient_exact<N>(p);
}

template <int N>
int in_sphere(const PointRefs<N + 2>& p) {
  double bound = 0.0;
  const double det =
      N == 2 ? incircle_fast(first<4>(p), bound) : insphere_fast(first<5>(p), bound);
  if (decided(det, bound)) return sign_of(det);
  const int on_grid = grid::in_sphere<N>(p);
  return on_grid != 2 ? on_grid : in_sphere_exact<N>(p);
}

template <int N>
int in_sphere_perturbed(const PointRefs<N + 2>& p, const std::array<std::int64_t, N + 2>& rank) {
  const int s = in_sphere<N>(p);
  if (s != 0) return s;
  std::array<int, N + 2> order;
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return rank[a] < rank[b]; });
  for (int i : order) {
    PointRefs<N + 1> rest;
    for (int j = 0, r = 0; j < N + 2; ++j)
      if (j != i) rest[r++] = p[j];
    const int o = orient<N>(rest);
    if (o != 0) return (i + N) % 2 == 0 ? o : -o;  // the cofactor sign (−1)^{i+N}
  }
  return 0;
}

template int orient<2>(const PointRefs<3>&);
template int orient<3>(const PointRefs<4>&);
template int in_sphere<2>(const PointRefs<4>&);
template int in_sphere<3>(const PointRefs<5>&);
template int in_sphere_perturbed<2>(const PointRefs<4>&, const std::array<std::int64_t, 4>&);
template int in_sphere_perturbed<3>(const PointRefs<5>&, const std::array<std::int64_t, 5>&);
template int orient_exact<2>(const PointRefs<3>&);
template int orient_exact<3>(const PointRefs<4>&);
template int in_sphere_exact<2>(const PointRefs<4>&);
template int in_sphere_exact<3>(const PointRefs<5>&);

}  // namespace shockfield::geometry
