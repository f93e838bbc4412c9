#pragma once
// s^-p and s^-q of the pair law φ(s) = [p s^-q − q s^-p]/(q − p) (eq 5 in reduced units), the only
// transcendental work of a pair: for the integer exponents of Table 1 by multiplication (a
// compile-time chain from 1/s² and, for an odd exponent, one √), else by std::pow.
#include <cmath>

namespace shockfield::macroparticle {

/// x^N by squaring, unrolled at compile time.
template <int N>
inline double power(double x) {
  if constexpr (N == 0) return 1.0;
  else if constexpr (N == 1) return x;
  else {
    const double half = power<N / 2>(x);
    if constexpr (N % 2 == 0) return half * half;
    else return half * half * x;
  }
}

/// s^-P and s^-Q from s² (P < Q fixed at compile time), returning 1/s²: one division, one √
/// only if P or Q is odd.
template <int P, int Q>
inline double inverse_powers(double s2, double& sp, double& sq) {
  const double s2inv = 1.0 / s2;
  if constexpr (P % 2 == 0 && Q % 2 == 0) {
    sp = power<P / 2>(s2inv);
    sq = sp * power<(Q - P) / 2>(s2inv);
  } else {
    const double sinv = std::sqrt(s2inv);
    sp = power<P / 2>(s2inv) * (P % 2 ? sinv : 1.0);
    sq = sp * power<(Q - P) / 2>(s2inv) * ((Q - P) % 2 ? sinv : 1.0);
  }
  return s2inv;
}

/// The same for exponents known at run time: a loop of multiplications for small integers
/// (1..32), std::pow otherwise.
class InversePowers {
 public:
  InversePowers(double p, double q)
      : p_(p), q_(q), ip_(small_integer(p) ? static_cast<int>(p) : 0), iq_(small_integer(q) ? static_cast<int>(q) : 0) {}
  /// True when p and q are both small integers (the multiply-only path).
  bool integer() const { return ip_ > 0 && iq_ > 0; }
  int ip() const { return ip_; }
  int iq() const { return iq_; }
  void operator()(double s, double& sp, double& sq) const {
    if (integer()) {
      const double sinv = 1.0 / s;
      sp = loop_power(sinv, ip_);
      sq = sp * loop_power(sinv, iq_ - ip_);
    } else {
      sp = std::pow(s, -p_);
      sq = std::pow(s, -q_);
    }
  }

 private:
  static bool small_integer(double v) { return v == std::floor(v) && v >= 1 && v <= 32; }
  static double loop_power(double x, int n) {
    double r = 1.0;
    for (int k = 0; k < n; ++k) r *= x;
    return r;
  }
  double p_, q_;
  int ip_, iq_;
};

}  // namespace shockfield::macroparticle
