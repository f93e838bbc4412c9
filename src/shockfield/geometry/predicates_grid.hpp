#pragma once
// The integer stage of the predicates (geometry/predicates.cpp), taken when the floating-point
// filter cannot decide and before the expansions: the coordinates of the N+1 or N+2 points are
// written as integers times one power of two, c = M·2^e with e the lowest set bit among them,
// and the determinant of the integer differences M_i − M_q is evaluated exactly in fixed-width
// integers. It equals the determinant of the differences p_i − q times a positive power of two,
// so the sign is the same. Exact lattices (a = 1: coordinates k/2) give differences below 2^23
// and 128-bit integers suffice; lattices of any constant (a = 3.615: coordinates of full 53-bit
// mantissas, all of about one magnitude) give |M| < 2^61 and use 320-bit integers (Wide). Points
// whose coordinates span more than 61 bits (a coordinate of 1e−17 beside one of 100) are left to
// the expansions.
//
// Bounds (b = bits of the largest difference): a 2×2 minor < 2^(2b+1), a lift Σ d_k² < 2^(2b+2),
// a 3×3 determinant < 3·2^(3b+1), a lift times it < 2^(5b+5), the in-sphere sum of four < 2^(5b+7).
// b <= 23: < 2^122 fits Int128; b <= 62: < 2^317 fits Wide (319 bits and a sign).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

namespace shockfield::geometry::grid {

__extension__ typedef __int128 Int128;  // GCC/Clang; __extension__ quiets -Wpedantic
__extension__ typedef unsigned __int128 Uint128;

/// A 320-bit two's-complement integer: + − × modulo 2^320, exact while results fit (see bounds).
struct Wide {
  static constexpr int kLimbs = 5;
  std::array<std::uint64_t, kLimbs> limb{};
  Wide() = default;
  friend Wide operator+(const Wide& a, const Wide& b) {
    Wide r;
    Uint128 carry = 0;
    for (int i = 0; i < kLimbs; ++i) {
      carry += Uint128{a.limb[i]} + b.limb[i];
      r.limb[i] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  Wide operator-() const {
    Wide r;
    for (int i = 0; i < kLimbs; ++i) r.limb[i] = ~limb[i];
    return r + Wide(1);
  }
  friend Wide operator-(const Wide& a, const Wide& b) { return a + -b; }
  Wide(Int128 v) {  // NOLINT: implicit, as for the built-in integers
    limb.fill(v < 0 ? ~std::uint64_t{0} : 0);
    limb[0] = static_cast<std::uint64_t>(v);
    limb[1] = static_cast<std::uint64_t>(static_cast<Uint128>(v) >> 64);
  }
  bool negative() const { return static_cast<std::int64_t>(limb[kLimbs - 1]) < 0; }
  /// Schoolbook product of the magnitudes' non-zero limbs, then the sign (exact while it fits).
  friend Wide operator*(const Wide& a, const Wide& b) {
    const Wide x = a.negative() ? -a : a, y = b.negative() ? -b : b;
    const int lx = x.length(), ly = y.length();
    Wide r;
    for (int i = 0; i < lx; ++i) {
      Uint128 carry = 0;
      int j = 0;
      for (; j < ly && i + j < kLimbs; ++j) {
        carry += Uint128{x.limb[i]} * y.limb[j] + r.limb[i + j];
        r.limb[i + j] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
      if (i + j < kLimbs) r.limb[i + j] = static_cast<std::uint64_t>(carry);
    }
    return a.negative() != b.negative() ? -r : r;
  }
  int length() const {  // limbs up to the highest non-zero one
    int n = kLimbs;
    while (n > 0 && limb[n - 1] == 0) --n;
    return n;
  }
  int sign() const {
    if (negative()) return -1;
    for (std::uint64_t l : limb)
      if (l != 0) return 1;
    return 0;
  }
};

inline int sign_of(Int128 x) { return (x > 0) - (x < 0); }
inline int sign_of(const Wide& x) { return x.sign(); }

/// The integer differences M_i − M_q of M points (q the last), or !valid when the coordinates
/// span more than kSpanBits bits (or are 0 everywhere, or beyond double's normal exponents).
template <int N, std::size_t M>
struct IntegerRows {
  static constexpr int kSpanBits = 61;
  std::int64_t d[M][N] = {};  // row M−1 stays zero
  int bits = 0;               ///< |d| < 2^bits
  bool valid = false;
  explicit IntegerRows(const std::array<const double*, M>& p) {
    // A normal double x = ±m·2^(f − 1075), m = 2^52 + the 52 stored bits, f its exponent field.
    std::uint64_t mantissa[M][N];
    int power[M][N] = {};
    int lowest = 1 << 20, highest = -(1 << 20);
    for (std::size_t i = 0; i < M; ++i)
      for (int k = 0; k < N; ++k) {
        const auto bits = std::bit_cast<std::uint64_t>(p[i][k]);
        const int field = static_cast<int>((bits >> 52) & 0x7ff);
        mantissa[i][k] = 0;
        if ((bits << 1) == 0) continue;       // ±0
        if (field == 0 || field == 0x7ff) return;  // subnormal (or not finite)
        mantissa[i][k] = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
        power[i][k] = field - 1075;
        lowest = std::min(lowest, power[i][k] + __builtin_ctzll(mantissa[i][k]));
        highest = std::max(highest, power[i][k] + 53);  // |x| < 2^highest
        if (bits >> 63) mantissa[i][k] |= std::uint64_t{1} << 63;  // the sign, kept aside
      }
    if (highest < lowest || highest - lowest > kSpanBits) return;
    auto integer = [&](std::size_t i, int k) -> std::int64_t {  // x·2^−lowest, below 2^61
      const std::uint64_t m = mantissa[i][k] & ~(std::uint64_t{1} << 63);
      if (m == 0) return 0;
      const int shift = power[i][k] - lowest;
      const auto v = static_cast<std::int64_t>(shift >= 0 ? m << shift : m >> -shift);
      return (mantissa[i][k] >> 63) ? -v : v;
    };
    std::int64_t largest = 0;
    for (std::size_t i = 0; i + 1 < M; ++i)
      for (int k = 0; k < N; ++k) {
        d[i][k] = integer(i, k) - integer(M - 1, k);  // below 2^62
        largest = std::max(largest, d[i][k] < 0 ? -d[i][k] : d[i][k]);
      }
    bits = 64 - __builtin_clzll(static_cast<std::uint64_t>(largest) | 1);
    valid = true;
  }
  // Minors (< 2^125) and lifts (< 2^126) fit 128 bits whatever the width of the rest.
  Int128 minor(int i, int j) const {
    return Int128{d[i][0]} * d[j][1] - Int128{d[j][0]} * d[i][1];
  }
  Int128 lift(int i) const {
    Int128 l = 0;
    for (int k = 0; k < N; ++k) l += Int128{d[i][k]} * d[i][k];
    return l;
  }
  /// det of rows i, j, k (3D): z_i m(j,k) − z_j m(i,k) + z_k m(i,j).
  template <class Int>
  Int det3(int i, int j, int k) const {
    return Int(d[i][2]) * Int(minor(j, k)) - Int(d[j][2]) * Int(minor(i, k)) +
           Int(d[k][2]) * Int(minor(i, j));
  }
  template <class Int>
  int orient_sign() const {
    if constexpr (N == 2)
      return sign_of(minor(0, 1));
    else
      return sign_of(det3<Int>(0, 1, 2));
  }
  /// The cofactor expansion along the lift column, as in predicates.cpp's other stages.
  template <class Int>
  int in_sphere_sign() const {
    if constexpr (N == 2)
      return sign_of(Int(lift(0)) * Int(minor(1, 2)) - Int(lift(1)) * Int(minor(0, 2)) +
                     Int(lift(2)) * Int(minor(0, 1)));
    else
      return sign_of((Int(lift(3)) * det3<Int>(0, 1, 2) - Int(lift(2)) * det3<Int>(0, 1, 3)) +
                     (Int(lift(1)) * det3<Int>(0, 2, 3) - Int(lift(0)) * det3<Int>(1, 2, 3)));
  }
};

constexpr int kInt128Bits = 23;  ///< differences below 2^23: the 128-bit evaluation (bounds above)

/// The exact sign of orient<N>, or 2 when the points are left to the expansions.
template <int N>
int orient(const std::array<const double*, N + 1>& p) {
  const IntegerRows<N, N + 1> r(p);
  if (!r.valid) return 2;
  return r.bits <= kInt128Bits ? r.template orient_sign<Int128>() : r.template orient_sign<Wide>();
}

/// The exact sign of in_sphere<N>, or 2 when the points are left to the expansions.
template <int N>
int in_sphere(const std::array<const double*, N + 2>& p) {
  const IntegerRows<N, N + 2> r(p);
  if (!r.valid) return 2;
  return r.bits <= kInt128Bits ? r.template in_sphere_sign<Int128>()
                               : r.template in_sphere_sign<Wide>();
}

}  // namespace shockfield::geometry::grid
