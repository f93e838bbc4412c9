#pragma once
// Small 3-vector helpers on std::array (Point3; not the Eigen Vec3 of core/types.hpp) shared by the rolling-ball code (rolling_ball.cpp, pivot_searches.cpp).
#include <array>

namespace shockfield::geometry {

using Point3 = std::array<double, 3>;

inline Point3 sub(const Point3& a, const Point3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double dot(const Point3& a, const Point3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Point3 add_scaled(const Point3& a, const Point3& b, double s) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

/// Circumcentre of a triangle in 3D: q − v0 = ((|a|² b − |b|² a) × (a × b)) / (2 |a × b|²).
inline Point3 triangle_circumcentre(const Point3& v0, const Point3& v1, const Point3& v2) {
  const Point3 a = sub(v1, v0), b = sub(v2, v0), n = cross(a, b);
  Point3 w;
  for (int k = 0; k < 3; ++k) w[k] = dot(a, a) * b[k] - dot(b, b) * a[k];
  return add_scaled(v0, cross(w, n), 0.5 / dot(n, n));
}

}  // namespace shockfield::geometry
