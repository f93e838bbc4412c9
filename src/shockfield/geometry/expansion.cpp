// Exact expansion arithmetic; the error-free transformations are Knuth's two-sum and Dekker's
// two-product with Veltkamp's split, as stated in Shewchuk (1997) Theorems 6, 7, 17, 18, 19.
#include "shockfield/geometry/expansion.hpp"

#include <algorithm>
#include <utility>

namespace shockfield::geometry {
namespace {

/// x + y = a + b exactly, x = fl(a + b) (Knuth's two-sum, Shewchuk Theorem 7).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

/// The same when |a| >= |b| (Dekker's fast two-sum, Shewchuk Theorem 6).
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

/// a = hi + lo with each half of at most 26 significant bits (Veltkamp split, Theorem 17).
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  hi = c - (c - a);
  lo = a - hi;
}

/// x + y = a·b exactly, x = fl(a·b) (Dekker's two-product, Theorem 18).
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err = x - ahi * bhi - alo * bhi - ahi * blo;
  y = alo * blo - err;
}

}  // namespace

Expansion& Expansion::operator=(const Expansion& o) {
  if (this == &o) return *this;
  size_ = 0;
  reserve(o.size_);
  std::copy(o.begin(), o.end(), data_);
  size_ = o.size_;
  return *this;
}

void Expansion::reserve(std::size_t n) {
  if (n <= capacity_) return;
  auto bigger = std::make_unique<double[]>(n);
  std::copy(begin(), end(), bigger.get());
  heap_ = std::move(bigger);
  data_ = heap_.get();
  capacity_ = n;
}

Expansion Expansion::difference(double a, double b) {
  Expansion e;
  double x, y;
  two_sum(a, -b, x, y);
  if (y != 0.0) e.push_back(y);
  if (x != 0.0) e.push_back(x);
  return e;
}

double Expansion::estimate() const {
  double s = 0.0;
  for (double p : *this) s += p;
  return s;
}

Expansion Expansion::scaled(double b) const {
  Expansion out;
  if (size_ == 0 || b == 0.0) return out;
  out.reserve(2 * size_);
  double q, h;
  two_product(data_[0], b, q, h);
  if (h != 0.0) out.push_back(h);
  for (std::size_t i = 1; i < size_; ++i) {
    double big, small, sum;
    two_product(data_[i], b, big, small);
    two_sum(q, small, sum, h);
    if (h != 0.0) out.push_back(h);
    fast_two_sum(big, sum, q, h);
    if (h != 0.0) out.push_back(h);
  }
  if (q != 0.0) out.push_back(q);
  return out;
}

Expansion operator+(const Expansion& e, const Expansion& f) {
  // FAST-EXPANSION-SUM with zero elimination (Shewchuk Theorem 13): merge the components by
  // magnitude, then one pass of two-sums. Needs strongly non-overlapping inputs, which every
  // expansion made here is (two-sum, scale and this sum keep that property under round-to-even).
  Expansion g;
  g.reserve(e.size_ + f.size_);
  std::merge(e.begin(), e.end(), f.begin(), f.end(), g.data_,
             [](double a, double b) { return std::abs(a) < std::abs(b); });
  g.size_ = e.size_ + f.size_;
  Expansion out;
  if (g.size_ == 0) return out;
  out.reserve(g.size_);
  double q = g.data_[0], sum, h;
  std::size_t i = 1;
  if (g.size_ > 1) {
    fast_two_sum(g.data_[1], q, sum, h);
    q = sum;
    if (h != 0.0) out.push_back(h);
    i = 2;
  }
  for (; i < g.size_; ++i) {
    two_sum(q, g.data_[i], sum, h);
    q = sum;
    if (h != 0.0) out.push_back(h);
  }
  if (q != 0.0) out.push_back(q);
  return out;
}

Expansion Expansion::operator-() const {
  Expansion out = *this;
  for (std::size_t i = 0; i < out.size_; ++i) out.data_[i] = -out.data_[i];
  return out;
}

Expansion operator-(const Expansion& e, const Expansion& f) { return e + (-f); }

Expansion operator*(const Expansion& e, const Expansion& f) {
  const Expansion& longer = e.size_ >= f.size_ ? e : f;
  const Expansion& shorter = &longer == &e ? f : e;
  Expansion out;
  for (double b : shorter) out = out + longer.scaled(b);
  return out;
}

}  // namespace shockfield::geometry
