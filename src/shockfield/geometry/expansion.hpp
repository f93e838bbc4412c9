#pragma once
// Exact floating-point expansions (Shewchuk, "Adaptive precision floating-point arithmetic and
// fast robust geometric predicates", Discrete Comput. Geom. 18, 1997, §2): a real number held
// exactly as a sum of doubles that do not overlap, in increasing order of magnitude, without
// zeros. Sums, differences and products of expansions are exact (barring overflow/underflow), so
// the sign of a determinant of double coordinates can be found exactly: the sign of the largest
// component. Written for geometry/predicates; needs IEEE round-to-nearest doubles (SSE2 on
// x86-64, never x87 extended precision).
#include <cmath>
#include <cstddef>
#include <memory>

namespace shockfield::geometry {

class Expansion {
 public:
  Expansion() = default;
  explicit Expansion(double x) {
    if (x != 0.0) push_back(x);
  }
  Expansion(const Expansion& o) { *this = o; }
  Expansion& operator=(const Expansion& o);

  /// The exact difference a − b as an expansion of at most two components.
  static Expansion difference(double a, double b);

  int sign() const { return size_ == 0 ? 0 : (data_[size_ - 1] > 0.0 ? 1 : -1); }
  /// The value rounded to a double (the largest components dominate).
  double estimate() const;
  std::size_t size() const { return size_; }
  const double* begin() const { return data_; }
  const double* end() const { return data_ + size_; }

  friend Expansion operator+(const Expansion& e, const Expansion& f);
  friend Expansion operator-(const Expansion& e, const Expansion& f);
  friend Expansion operator*(const Expansion& e, const Expansion& f);
  Expansion operator-() const;

 private:
  /// This expansion times one double (Shewchuk's SCALE-EXPANSION with zero elimination).
  Expansion scaled(double b) const;

  // Components in a small inline buffer (no allocation for the lengths the predicates meet on
  // ordinary input), moved to the heap when longer.
  static constexpr std::size_t kInline = 40;
  void push_back(double x) {
    if (size_ == capacity_) reserve(2 * capacity_);
    data_[size_++] = x;
  }
  void reserve(std::size_t n);

  double inline_[kInline];
  std::unique_ptr<double[]> heap_;
  double* data_ = inline_;
  std::size_t size_ = 0, capacity_ = kInline;
};

}  // namespace shockfield::geometry
