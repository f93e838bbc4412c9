// The turning ball of MS1/MS3 (pivot_searches.hpp): its circle, the angle at which it meets a
// point, and the first angle at which it touches a sphere.
#include "shockfield/geometry/pivot_searches.hpp"

namespace shockfield::geometry {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The angles θ at which the ball's centre c(θ) lies within `reach` of `target`:
/// (p_x cos θ + p_y sin θ ≥ κ, p = target − m) gives θ ∈ [φ − α, φ + α]. Returns {φ − α, α};
/// α = +inf for every θ, NaN for none.
std::pair<double, double> reach_interval(const PivotCircle& c, const Point3& target, double reach) {
  const Point3 p = sub(target, c.centre);
  const double px = dot(p, c.x), py = dot(p, c.y);
  const double q = std::hypot(px, py);
  const double kappa = (c.radius * c.radius + dot(p, p) - reach * reach) / (2.0 * c.radius);
  if (kappa <= -q) return {0.0, std::numeric_limits<double>::infinity()};
  if (kappa > q) return {0.0, std::numeric_limits<double>::quiet_NaN()};
  const double alpha = std::acos(kappa / q);
  return {std::atan2(py, px) - alpha, alpha};
}

}  // namespace

std::optional<PivotCircle> pivot_about_axis(const Point3& on_axis, const Point3& axis,
                                            const Point3& start, double r) {
  const double length = std::sqrt(dot(axis, axis));
  if (!(length > 0.0) || !(r > 0.0)) return std::nullopt;
  PivotCircle c;
  c.ball_radius = r;
  c.z = {axis[0] / length, axis[1] / length, axis[2] / length};
  const Point3 d = sub(start, on_axis);
  c.centre = add_scaled(on_axis, c.z, dot(d, c.z));
  const Point3 w = sub(start, c.centre);
  c.radius = std::sqrt(dot(w, w));
  if (!(c.radius > 1e-12 * std::sqrt(dot(d, d)))) return std::nullopt;
  c.x = {w[0] / c.radius, w[1] / c.radius, w[2] / c.radius};
  c.y = cross(c.z, c.x);
  return c;
}

std::optional<PivotCircle> pivot_about_edge(const Point3& a, const Point3& b, const Point3& c, double r) {
  // r_o: the centre of the ball of radius r through A, B, C above the triangle, at height
  // h = √(r² − ρ²) over its circumcentre q (ρ the circumradius) along the unit normal.
  const Point3 n = cross(sub(b, a), sub(c, a));
  const double n_length = std::sqrt(dot(n, n));
  if (!(n_length > 0.0)) return std::nullopt;
  const Point3 q = triangle_circumcentre(a, b, c);
  const Point3 qa = sub(a, q);
  const double h2 = r * r - dot(qa, qa);
  if (!(h2 >= 0.0)) return std::nullopt;
  const Point3 start = add_scaled(q, n, std::sqrt(h2) / n_length);
  return pivot_about_axis(a, sub(b, a), start, r);
}

double angle_met(const PivotCircle& pivot, const Point3& p) {
  const auto [first, alpha] = reach_interval(pivot, p, pivot.ball_radius);
  if (!(alpha < std::numbers::pi))
    return std::numeric_limits<double>::infinity();  // never or always inside
  const double theta = first < -kMetAtStart ? first + kTwoPi : first;
  return std::max(theta, 0.0);
}

double first_angle_touching(const PivotCircle& pivot, const Point3& centre, double radius) {
  // Widened by 1e-9 relative, and the angle lowered by 1e-6 rad, so that rounding in the value
  // function (acos near ±1) never puts a point below its cube's bound.
  constexpr double kSlack = 1e-6;
  const double reach = (pivot.ball_radius + radius) * (1.0 + 1e-9);
  const auto [first, alpha] = reach_interval(pivot, centre, reach);
  if (std::isnan(alpha)) return std::numeric_limits<double>::infinity();
  if (!(alpha < std::numbers::pi)) return 0.0;
  const double s = first < 0.0 ? first + kTwoPi : first;
  if (s <= kSlack || s + 2.0 * alpha >= kTwoPi - kSlack) return 0.0;  // touching at the start
  return s - kSlack;
}

}  // namespace shockfield::geometry
