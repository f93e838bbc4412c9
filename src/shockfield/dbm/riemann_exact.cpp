#include "shockfield/dbm/riemann_exact.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {

ExactRiemann::ExactRiemann(const Primitive& left, const Primitive& right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  if (!(left.rho > 0 && right.rho > 0 && left.p > 0 && right.p > 0 && gamma > 1))
    throw InputError("exact Riemann solver: densities, pressures must be > 0 and gamma > 1");
  c_left_ = std::sqrt(gamma * left.p / left.rho);
  c_right_ = std::sqrt(gamma * right.p / right.rho);
  if (2.0 / (gamma - 1.0) * (c_left_ + c_right_) <= right.u - left.u)
    throw InputError("exact Riemann solver: the initial jump generates a vacuum");
  double p = std::max(1e-8, 0.5 * (left.p + right.p) - 0.125 * (right.u - left.u) *
                                                             (left.rho + right.rho) *
                                                             (c_left_ + c_right_));
  for (int it = 0; it < 100; ++it) {
    double fl, dfl, fr, dfr;
    pressure_function(p, left_, c_left_, fl, dfl);
    pressure_function(p, right_, c_right_, fr, dfr);
    const double next = std::max(1e-12, p - (fl + fr + right.u - left.u) / (dfl + dfr));
    const double change = 2.0 * std::abs(next - p) / (next + p);
    p = next;
    if (change < 1e-14) break;
  }
  double fl, dfl, fr, dfr;
  pressure_function(p, left_, c_left_, fl, dfl);
  pressure_function(p, right_, c_right_, fr, dfr);
  star_.p = p;
  star_.u = 0.5 * (left.u + right.u) + 0.5 * (fr - fl);
  const double g = (gamma - 1.0) / (gamma + 1.0);
  auto star_density = [&](const Primitive& s) {
    const double r = p / s.p;
    return r > 1.0 ? s.rho * (r + g) / (g * r + 1.0) : s.rho * std::pow(r, 1.0 / gamma);
  };
  star_.rho_left = star_density(left_);
  star_.rho_right = star_density(right_);
}

void ExactRiemann::pressure_function(double p, const Primitive& s, double c, double& f,
                                     double& df) const {
  const double g = gamma_;
  if (p > s.p) {  // shock
    const double A = 2.0 / ((g + 1.0) * s.rho);
    const double B = (g - 1.0) / (g + 1.0) * s.p;
    const double q = std::sqrt(A / (p + B));
    f = (p - s.p) * q;
    df = q * (1.0 - 0.5 * (p - s.p) / (B + p));
  } else {  // rarefaction
    const double r = p / s.p;
    f = 2.0 * c / (g - 1.0) * (std::pow(r, (g - 1.0) / (2.0 * g)) - 1.0);
    df = 1.0 / (s.rho * c) * std::pow(r, -(g + 1.0) / (2.0 * g));
  }
}

double ExactRiemann::right_shock_speed() const {
  if (star_.p <= right_.p) return std::numeric_limits<double>::quiet_NaN();
  const double g = gamma_;
  return right_.u + c_right_ * std::sqrt((g + 1.0) / (2.0 * g) * star_.p / right_.p +
                                         (g - 1.0) / (2.0 * g));
}

Primitive ExactRiemann::sample(double xi) const {
  const double g = gamma_;
  // Work on the left side; the right side is the mirror image (x → −x, u → −u).
  const bool left_side = xi <= star_.u;
  const Primitive s = left_side ? left_ : Primitive{right_.rho, -right_.u, right_.p};
  const double c = left_side ? c_left_ : c_right_;
  const double x = left_side ? xi : -xi;
  const double us = left_side ? star_.u : -star_.u;
  const double rho_star = left_side ? star_.rho_left : star_.rho_right;
  Primitive out;
  if (star_.p > s.p) {  // shock moving to −x
    const double speed = s.u - c * std::sqrt((g + 1.0) / (2.0 * g) * star_.p / s.p +
                                             (g - 1.0) / (2.0 * g));
    out = x < speed ? s : Primitive{rho_star, us, star_.p};
  } else {  // rarefaction fan between head and tail
    const double c_star = c * std::pow(star_.p / s.p, (g - 1.0) / (2.0 * g));
    const double head = s.u - c, tail = us - c_star;
    if (x < head) {
      out = s;
    } else if (x > tail) {
      out = {rho_star, us, star_.p};
    } else {
      const double k = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * c) * (s.u - x);
      out = {s.rho * std::pow(k, 2.0 / (g - 1.0)),
             2.0 / (g + 1.0) * (c + (g - 1.0) / 2.0 * s.u + x), s.p * std::pow(k, 2.0 * g / (g - 1.0))};
    }
  }
  if (!left_side) out.u = -out.u;
  return out;
}

}  // namespace shockfield::dbm
