// Rolling-ball surface from the Delaunay division (rolling_ball.hpp).
#include "shockfield/geometry/rolling_ball.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/predicates.hpp"

namespace shockfield::geometry {
namespace {

using P3 = std::array<double, 3>;

P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
P3 add_scaled(const P3& a, const P3& b, double s) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

/// Circumcentre of a tetrahedron: c − v0 = (|a|² (b×c) + |b|² (c×a) + |c|² (a×b)) / (2 a·(b×c)).
P3 tet_circumcentre(const P3& v0, const P3& v1, const P3& v2, const P3& v3) {
  const P3 a = sub(v1, v0), b = sub(v2, v0), c = sub(v3, v0);
  const P3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  const double s = 0.5 / dot(a, bc);
  P3 r = v0;
  for (int k = 0; k < 3; ++k) r[k] += s * (dot(a, a) * bc[k] + dot(b, b) * ca[k] + dot(c, c) * ab[k]);
  return r;
}

/// Circumcentre of a triangle in 3D: q − v0 = ((|a|² b − |b|² a) × (a × b)) / (2 |a × b|²).
P3 triangle_circumcentre(const P3& v0, const P3& v1, const P3& v2) {
  const P3 a = sub(v1, v0), b = sub(v2, v0), n = cross(a, b);
  P3 w;
  for (int k = 0; k < 3; ++k) w[k] = dot(a, a) * b[k] - dot(b, b) * a[k];
  return add_scaled(v0, cross(w, n), 0.5 / dot(n, n));
}

}  // namespace

TriangleSurface rolling_ball_surface(const DelaunayDivision<3>& d, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError(fmt::format("rolling-ball radius must be a positive finite length, got {}", radius));
  const auto& S = d.simplices;
  const auto& X = d.points;
  const std::size_t ns = S.size();
  std::vector<P3> centre(ns);
  for (std::size_t t = 0; t < ns; ++t)
    centre[t] = tet_circumcentre(X[S[t][0]], X[S[t][1]], X[S[t][2]], X[S[t][3]]);
  auto circumradius = [&](std::size_t t) { return std::sqrt(dot(sub(centre[t], X[S[t][0]]), sub(centre[t], X[S[t][0]]))); };
  // Face i of tet t, ordered so that its normal points out of t (orient(face, v_i) > 0 means
  // the right-hand normal of the face points away from v_i).
  auto outward_face = [&](std::size_t t, int i) {
    std::array<std::int32_t, 3> f;
    for (int j = 0, r = 0; j < 4; ++j)
      if (j != i) f[r++] = S[t][j];
    if (orient<3>({X[f[0]].data(), X[f[1]].data(), X[f[2]].data(), X[S[t][i]].data()}) < 0)
      std::swap(f[1], f[2]);
    return f;
  };
  // Can a ball of radius r move through face i of t (to its neighbour, or to infinity)? The
  // Voronoi edge of the face runs along its normal through the face's circumcentre q.
  auto passable = [&](std::size_t t, int i) {
    const auto f = outward_face(t, i);
    const P3 q = triangle_circumcentre(X[f[0]], X[f[1]], X[f[2]]);
    const double rho = std::sqrt(dot(sub(q, X[f[0]]), sub(q, X[f[0]])));
    const P3 nu = cross(sub(X[f[1]], X[f[0]]), sub(X[f[2]], X[f[0]]));  // out of t
    const double ht = dot(sub(centre[t], q), nu);
    const std::int32_t n = d.neighbours[t][i];
    const double hn = n < 0 ? INFINITY : dot(sub(centre[n], q), nu);
    const bool crosses_plane = std::min(ht, hn) <= 0.0 && std::max(ht, hn) >= 0.0;
    const double least = crosses_plane ? rho
                                       : std::min(circumradius(t), n < 0 ? INFINITY : circumradius(n));
    return least > radius;
  };
  // The exterior E: flood from infinity (the hull faces) through passable faces.
  std::vector<char> exterior(ns, 0);
  std::vector<std::int32_t> stack;
  for (std::size_t t = 0; t < ns; ++t)
    for (int i = 0; i < 4; ++i)
      if (d.neighbours[t][i] < 0 && !exterior[t] && passable(t, i)) {
        exterior[t] = 1;
        stack.push_back(static_cast<std::int32_t>(t));
      }
  while (!stack.empty()) {
    const std::int32_t t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 4; ++i) {
      const std::int32_t n = d.neighbours[t][i];
      if (n >= 0 && !exterior[n] && passable(t, i)) {
        exterior[n] = 1;
        stack.push_back(n);
      }
    }
  }
  // Faces where a ball of E is stopped, normal towards E.
  TriangleSurface s;
  s.points = X;
  for (std::size_t t = 0; t < ns; ++t)
    for (int i = 0; i < 4; ++i) {
      const std::int32_t n = d.neighbours[t][i];
      if (n >= 0 && n < static_cast<std::int32_t>(t)) continue;  // each face once
      const bool in_t = exterior[t], in_n = n < 0 || exterior[n];
      if (!in_t && !in_n) continue;
      const bool open = passable(t, i);
      auto f = outward_face(t, i);  // normal towards n
      if (in_n && (!in_t || !open)) s.triangles.push_back(f);
      if (in_t && (!in_n || !open)) s.triangles.push_back({f[0], f[2], f[1]});
    }
  if (s.triangles.empty())
    throw InputError(fmt::format("a ball of radius {} passes between the points everywhere and "
                                 "touches no surface: give a larger radius",
                                 radius));
  std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
  std::vector<char> used(X.size(), 0);
  for (const auto& f : s.triangles) {
    const P3 a = X[f[0]], b = X[f[1]], c = X[f[2]];
    const P3 n = cross(sub(b, a), sub(c, a));
    s.area += 0.5 * std::sqrt(dot(n, n));
    s.volume += dot(a, cross(b, c)) / 6.0;
    for (int k = 0; k < 3; ++k) {
      ++directed[{f[k], f[(k + 1) % 3]}];
      used[f[k]] = 1;
    }
  }
  std::size_t edges = 0;
  s.manifold = true;
  for (const auto& [e, count] : directed) {
    const auto back = directed.find({e.second, e.first});
    const int reverse = back == directed.end() ? 0 : back->second;
    if (count != 1 || reverse != 1) s.manifold = false;
    if (e.first < e.second || reverse == 0) ++edges;
  }
  const auto vertices = std::count(used.begin(), used.end(), 1);
  s.euler_characteristic = static_cast<std::int64_t>(vertices) - static_cast<std::int64_t>(edges) +
                           static_cast<std::int64_t>(s.triangles.size());
  return s;
}

}  // namespace shockfield::geometry
