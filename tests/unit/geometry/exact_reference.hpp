#pragma once
// Brute-force exact reference for the predicate tests, independent of geometry/expansion: every
// double is an integer times 2^−kShift (for the magnitudes the tests use, |x| in [2^−60, 2^60]),
// so determinants of the un-translated matrices [(p, 1)] and [(p, |p|², 1)] are evaluated in
// arbitrary-size integers (sign-magnitude, 32-bit limbs) by cofactor expansion. Slow and simple.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shockfield::geometry::test {

class BigInt {
 public:
  BigInt() = default;
  explicit BigInt(std::int64_t v) : negative_(v < 0) {
    std::uint64_t m = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    while (m) {
      limbs_.push_back(static_cast<std::uint32_t>(m));
      m >>= 32;
    }
  }
  /// x · 2^shift exactly; x·2^shift must be an integer.
  static BigInt from_double(double x, int shift) {
    int exp = 0;
    const double mant = std::frexp(x, &exp);               // x = mant · 2^exp, |mant| in [0.5, 1)
    const auto m = static_cast<std::int64_t>(std::ldexp(mant, 53));  // x = m · 2^(exp − 53)
    BigInt r(m);
    const int s = exp - 53 + shift;
    if (s >= 0) return r.shifted(s);
    // Drop the trailing zero bits; the remainder must be zero.
    std::int64_t mm = m;
    for (int k = 0; k < -s; ++k) mm /= 2;
    return BigInt(mm);
  }
  int sign() const { return limbs_.empty() ? 0 : (negative_ ? -1 : 1); }

  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    if (a.negative_ == b.negative_) return with_sign(add_mag(a.limbs_, b.limbs_), a.negative_);
    if (less_mag(a.limbs_, b.limbs_)) return with_sign(sub_mag(b.limbs_, a.limbs_), b.negative_);
    return with_sign(sub_mag(a.limbs_, b.limbs_), a.negative_);
  }
  friend BigInt operator-(const BigInt& a, const BigInt& b) {
    BigInt nb = b;
    nb.negative_ = !nb.negative_;
    return a + nb;
  }
  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    std::vector<std::uint32_t> r(a.limbs_.size() + b.limbs_.size(), 0);
    for (std::size_t i = 0; i < a.limbs_.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.limbs_.size(); ++j) {
        const std::uint64_t t = std::uint64_t(a.limbs_[i]) * b.limbs_[j] + r[i + j] + carry;
        r[i + j] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
      r[i + b.limbs_.size()] += static_cast<std::uint32_t>(carry);
    }
    return with_sign(std::move(r), a.negative_ != b.negative_);
  }

 private:
  using Mag = std::vector<std::uint32_t>;
  static BigInt with_sign(Mag m, bool negative) {
    while (!m.empty() && m.back() == 0) m.pop_back();
    BigInt r;
    r.limbs_ = std::move(m);
    r.negative_ = !r.limbs_.empty() && negative;
    return r;
  }
  BigInt shifted(int bits) const {
    BigInt two(2), r = *this;
    for (int k = 0; k < bits; ++k) r = r * two;
    return r;
  }
  static bool less_mag(const Mag& a, const Mag& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    for (std::size_t i = a.size(); i-- > 0;)
      if (a[i] != b[i]) return a[i] < b[i];
    return false;
  }
  static Mag add_mag(const Mag& a, const Mag& b) {
    Mag r(std::max(a.size(), b.size()) + 1, 0);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const std::uint64_t t = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
      r[i] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    return r;
  }
  static Mag sub_mag(const Mag& a, const Mag& b) {  // |a| >= |b|
    Mag r(a.size(), 0);
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::int64_t t = std::int64_t(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
      borrow = t < 0;
      if (t < 0) t += std::int64_t(1) << 32;
      r[i] = static_cast<std::uint32_t>(t);
    }
    return r;
  }
  Mag limbs_;
  bool negative_ = false;
};

constexpr int kShift = 64;  // coordinates are integer multiples of 2^−64 in every test

inline BigInt big_determinant(const std::vector<std::vector<BigInt>>& m) {
  const std::size_t n = m.size();
  if (n == 1) return m[0][0];
  BigInt det;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::vector<BigInt>> minor;
    for (std::size_t r = 0; r < n; ++r)
      if (r != i) minor.emplace_back(m[r].begin() + 1, m[r].end());
    const BigInt term = m[i][0] * big_determinant(minor);
    det = i % 2 == 0 ? det + term : det - term;
  }
  return det;
}

/// Sign of det[(p_i, 1)] for N+1 points of N coordinates.
template <int N>
int reference_orient(const std::array<const double*, N + 1>& p) {
  std::vector<std::vector<BigInt>> m;
  for (const double* q : p) {
    std::vector<BigInt> row;
    for (int k = 0; k < N; ++k) row.push_back(BigInt::from_double(q[k], kShift));
    row.emplace_back(std::int64_t(1));
    m.push_back(row);
  }
  return big_determinant(m).sign();
}

/// Sign of det[(p_i, |p_i|², 1)] for N+2 points (equal to the translated in-sphere determinant).
template <int N>
int reference_in_sphere(const std::array<const double*, N + 2>& p) {
  std::vector<std::vector<BigInt>> m;
  for (const double* q : p) {
    std::vector<BigInt> row;
    BigInt lift;
    for (int k = 0; k < N; ++k) {
      row.push_back(BigInt::from_double(q[k], kShift));
      lift = lift + row.back() * row.back();
    }
    // Scale the (p, 1) columns so that all columns share the factor 2^kShift per coordinate:
    // det[(2^s p, 2^2s |p|², 1)] = 2^{(N+2)s} det[(p, |p|², 1)], the sign is unchanged.
    row.push_back(lift);
    row.emplace_back(std::int64_t(1));
    m.push_back(row);
  }
  return big_determinant(m).sign();
}

}  // namespace shockfield::geometry::test
