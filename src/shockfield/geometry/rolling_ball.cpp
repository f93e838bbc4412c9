// Rolling-ball surface from the Delaunay division (rolling_ball.hpp).
#include "shockfield/geometry/rolling_ball.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/predicates.hpp"
#include "shockfield/geometry/vec3.hpp"

namespace shockfield::geometry {
namespace {

using P3 = Point3;

/// Circumcentre of a tetrahedron: c − v0 = (|a|² (b×c) + |b|² (c×a) + |c|² (a×b)) / (2 a·(b×c)).
P3 tet_circumcentre(const P3& v0, const P3& v1, const P3& v2, const P3& v3) {
  const P3 a = sub(v1, v0), b = sub(v2, v0), c = sub(v3, v0);
  const P3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  const double s = 0.5 / dot(a, bc);
  P3 r = v0;
  for (int k = 0; k < 3; ++k) r[k] += s * (dot(a, a) * bc[k] + dot(b, b) * ca[k] + dot(c, c) * ab[k]);
  return r;
}

// How the exterior grows over one division: a ball of radius r rolling between the cells
// (rolling_ball_surface, rolling_ball_cavities) or sculpting to depth s (packing_sculpting_surface).
enum class Growth { roll, sculpt };

// The exterior's moves over one division: circumcentres of the tetrahedra and whether the exterior
// passes a face.
class BallPassage {
 public:
  BallPassage(const DelaunayDivision<3>& d, double radius, Growth growth = Growth::roll)
      : d_(d), radius_(radius), growth_(growth), centre_(d.simplices.size()) {
    if (!(radius > 0.0) || !std::isfinite(radius))
      throw InputError(fmt::format("{} must be a positive finite length, got {}",
                                   growth == Growth::roll ? "rolling-ball radius" : "sculpting depth", radius));
    const auto& S = d.simplices;
    const auto& X = d.points;
    for (std::size_t t = 0; t < S.size(); ++t)
      centre_[t] = tet_circumcentre(X[S[t][0]], X[S[t][1]], X[S[t][2]], X[S[t][3]]);
  }
  double circumradius(std::size_t t) const {
    const P3 r = sub(centre_[t], d_.points[d_.simplices[t][0]]);
    return std::sqrt(dot(r, r));
  }
  /// Face i of tet t, ordered so that its normal points out of t (orient(face, v_i) > 0 means the
  /// right-hand normal of the face points away from v_i).
  std::array<std::int32_t, 3> outward_face(std::size_t t, int i) const {
    const auto& X = d_.points;
    std::array<std::int32_t, 3> f;
    for (int j = 0, r = 0; j < 4; ++j)
      if (j != i) f[r++] = d_.simplices[t][j];
    if (orient<3>({X[f[0]].data(), X[f[1]].data(), X[f[2]].data(), X[d_.simplices[t][i]].data()}) < 0)
      std::swap(f[1], f[2]);
    return f;
  }
  /// Can the ball move through face i of t (to its neighbour, or to infinity)? The Voronoi edge of
  /// the face runs along its normal through the face's circumcentre.
  bool passable(std::size_t t, int i) const {
    const FaceAxis a = axis(t, i);
    const std::int32_t n = d_.neighbours[t][i];
    const bool crosses_plane = std::min(a.ht, a.hn) <= 0.0 && std::max(a.ht, a.hn) >= 0.0;
    const double least = crosses_plane ? a.rho : std::min(circumradius(t), n < 0 ? INFINITY : circumradius(n));
    return least > radius_;
  }
  /// Does the exterior grow through face i of t into the cell behind it — the neighbour, or t itself
  /// when `into_t` (from infinity through a hull face)? Rolling: `passable`. Sculpting (Xu et al.
  /// 2015): the sphere through the face's vertices, its centre coming from infinity on the exterior
  /// side along the face's axis, first meets a point P at the inner cell's circumsphere (that cell
  /// is Delaunay: no point is met before). Its radius √(ρ² + h²) (h: the centre's height above the
  /// face) falls to the face's circumradius ρ at h = 0, so the least radius before P is met is the
  /// inner cell's circumradius when its centre is on the exterior side (h ≥ 0), else ρ; the cell
  /// is sculpted when that least radius exceeds the depth s.
  bool grows(std::size_t t, int i, bool into_t) const {
    if (growth_ == Growth::roll) return passable(t, i);
    const FaceAxis a = axis(t, i);
    const double h_inner = into_t ? a.ht : -a.hn;  // the inner centre's height towards the exterior
    const double least = h_inner >= 0.0 ? circumradius(into_t ? t : static_cast<std::size_t>(d_.neighbours[t][i])) : a.rho;
    return least > radius_;
  }
  /// Marks with `label` every cell the exterior reaches from the cells already on `stack`.
  void flood(std::vector<std::int32_t>& stack, std::vector<std::int32_t>& region, std::int32_t label) const {
    while (!stack.empty()) {
      const std::int32_t t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i) {
        const std::int32_t n = d_.neighbours[t][i];
        if (n >= 0 && region[n] == kNone && grows(t, i, false)) {
          region[n] = label;
          stack.push_back(n);
        }
      }
    }
  }
  /// The exterior (label 0): the cells reached from infinity through the hull faces; the others kNone.
  std::vector<std::int32_t> exterior() const {
    std::vector<std::int32_t> region(d_.simplices.size(), kNone);
    std::vector<std::int32_t> stack;
    for (std::size_t t = 0; t < region.size(); ++t)
      for (int i = 0; i < 4; ++i)
        if (d_.neighbours[t][i] < 0 && region[t] == kNone && grows(t, i, true)) {
          region[t] = 0;
          stack.push_back(static_cast<std::int32_t>(t));
        }
    flood(stack, region, 0);
    return region;
  }
  static constexpr std::int32_t kNone = -1;

 private:
  /// Face i of t: its circumradius ρ and the heights of the circumcentres of t and of its
  /// neighbour (+∞ on the hull) above the face's plane, along the normal out of t (in units of
  /// that unnormalised normal: only their signs are used).
  struct FaceAxis {
    double rho, ht, hn;
  };
  FaceAxis axis(std::size_t t, int i) const {
    const auto& X = d_.points;
    const auto f = outward_face(t, i);
    const P3 q = triangle_circumcentre(X[f[0]], X[f[1]], X[f[2]]);
    const P3 nu = cross(sub(X[f[1]], X[f[0]]), sub(X[f[2]], X[f[0]]));  // out of t
    const std::int32_t n = d_.neighbours[t][i];
    return {std::sqrt(dot(sub(q, X[f[0]]), sub(q, X[f[0]]))), dot(sub(centre_[t], q), nu),
            n < 0 ? INFINITY : dot(sub(centre_[n], q), nu)};
  }
  const DelaunayDivision<3>& d_;
  double radius_;
  Growth growth_;
  std::vector<P3> centre_;
};

// Solid angle at vertex p of the tetrahedron (p, a, b, c) (Van Oosterom & Strackee 1983):
// tan(ω/2) = |A·(B×C)| / (|A||B||C| + (A·B)|C| + (A·C)|B| + (B·C)|A|), A = a − p, ...
double vertex_solid_angle(const P3& p, const P3& a, const P3& b, const P3& c) {
  const P3 A = sub(a, p), B = sub(b, p), C = sub(c, p);
  const double la = std::sqrt(dot(A, A)), lb = std::sqrt(dot(B, B)), lc = std::sqrt(dot(C, C));
  const double denominator = la * lb * lc + dot(A, B) * lc + dot(A, C) * lb + dot(B, C) * la;
  return 2.0 * std::atan2(std::abs(dot(A, cross(B, C))), denominator);
}

/// Σ over the four vertices of tetrahedron t of their solid angles in it (sr); 0 for a flat cell.
/// A Delaunay division of a lattice holds cells of four coplanar points (cospherical ties broken
/// symbolically), flat up to round-off. Their vertex solid angles are 0 or 2π depending on which
/// side round-off puts a point, not on the geometry, and moved the atoms' volume of a domain by
/// 0.24 % when the same domain sat elsewhere in the box (cli.analyze_domains, corner copy). A cell
/// of no volume covers no solid angle: it is left out. Flat means |A·(B×C)| ≤ 1e-10 |A||B||C|
/// at vertex 0 (lattice ties measure ~1e-16; a physical cell that thin has probability ~1e-10).
double cell_vertex_solid_angle(const DelaunayDivision<3>& d, std::size_t t) {
  const auto& q = d.simplices[t];
  const P3 A = sub(d.points[q[1]], d.points[q[0]]), B = sub(d.points[q[2]], d.points[q[0]]),
           C = sub(d.points[q[3]], d.points[q[0]]);
  if (std::abs(dot(A, cross(B, C))) <= 1e-10 * std::sqrt(dot(A, A) * dot(B, B) * dot(C, C))) return 0;
  double sum = 0;
  for (int j = 0; j < 4; ++j)
    sum += vertex_solid_angle(d.points[q[j]], d.points[q[(j + 1) % 4]], d.points[q[(j + 2) % 4]], d.points[q[(j + 3) % 4]]);
  return sum;
}

/// Σ of cell_vertex_solid_angle over the cells outside the exterior (region ≠ 0).
double enclosed_solid_angle(const DelaunayDivision<3>& d, const std::vector<std::int32_t>& region) {
  double sum = 0;
  for (std::size_t t = 0; t < d.simplices.size(); ++t)
    if (region[t] != 0) sum += cell_vertex_solid_angle(d, t);
  return sum;
}

}  // namespace

void measure_surface(TriangleSurface& s) {
  const auto& X = s.points;
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
}

TriangleSurface rolling_ball_surface(const DelaunayDivision<3>& d, double radius) {
  return rolling_ball_solid(d, radius).surface;
}

EnclosedSolid rolling_ball_solid(const DelaunayDivision<3>& d, double radius) {
  const BallPassage ball(d, radius);
  const std::vector<std::int32_t> region = ball.exterior();
  EnclosedSolid solid;
  solid.vertex_solid_angle = enclosed_solid_angle(d, region);
  // Faces where a ball of E is stopped, normal towards E.
  TriangleSurface& s = solid.surface;
  s.points = d.points;
  for (std::size_t t = 0; t < d.simplices.size(); ++t)
    for (int i = 0; i < 4; ++i) {
      const std::int32_t n = d.neighbours[t][i];
      if (n >= 0 && n < static_cast<std::int32_t>(t)) continue;  // each face once
      const bool in_t = region[t] == 0, in_n = n < 0 || region[n] == 0;
      if (!in_t && !in_n) continue;
      const bool open = ball.passable(t, i);
      auto f = ball.outward_face(t, i);  // normal towards n
      if (in_n && (!in_t || !open)) s.triangles.push_back(f);
      if (in_t && (!in_n || !open)) s.triangles.push_back({f[0], f[2], f[1]});
    }
  if (s.triangles.empty())
    throw InputError(fmt::format("a ball of radius {} passes between the points everywhere and "
                                 "touches no surface: give a larger radius",
                                 radius));
  measure_surface(s);
  return solid;
}

TriangleSurface packing_sculpting_surface(const DelaunayDivision<3>& d, double depth) {
  return packing_sculpting_solid(d, depth).surface;
}

EnclosedSolid packing_sculpting_solid(const DelaunayDivision<3>& d, double depth) {
  const BallPassage sculptor(d, depth, Growth::sculpt);
  const std::vector<std::int32_t> region = sculptor.exterior();
  EnclosedSolid solid;
  solid.vertex_solid_angle = enclosed_solid_angle(d, region);
  // The boundary of the cells left, normals out of them.
  TriangleSurface& s = solid.surface;
  s.points = d.points;
  for (std::size_t t = 0; t < d.simplices.size(); ++t) {
    if (region[t] == 0) continue;
    for (int i = 0; i < 4; ++i) {
      const std::int32_t n = d.neighbours[t][i];
      if (n < 0 || region[n] == 0) s.triangles.push_back(sculptor.outward_face(t, i));
    }
  }
  if (s.triangles.empty())
    throw InputError(fmt::format("sculpting to depth {} removes every tetrahedron and leaves no "
                                 "surface: give a larger depth (about the point spacing or more)",
                                 depth));
  measure_surface(s);
  if (!s.manifold)
    throw InputError(fmt::format("sculpting to depth {} carves between the points in places and leaves a "
                                 "surface that is not a manifold (an edge on more than two triangles): give a "
                                 "larger depth (about the point spacing or more)",
                                 depth));
  return solid;
}

std::vector<Cavity> rolling_ball_cavities(const DelaunayDivision<3>& d, double radius) {
  const BallPassage ball(d, radius);
  std::vector<std::int32_t> region = ball.exterior();
  std::vector<Cavity> cavities;
  std::vector<std::int32_t> stack;
  for (std::size_t t = 0; t < region.size(); ++t) {
    if (region[t] != BallPassage::kNone || !(ball.circumradius(t) > radius)) continue;
    // A flat tetrahedron of four cospherical points (a lattice's degenerate split) has no room
    // for a ball whatever its computed circumradius: it seeds no cavity.
    if (simplex_volume<3>(d, t) < 1e-9 * std::pow(ball.circumradius(t), 3)) continue;
    const auto label = static_cast<std::int32_t>(cavities.size()) + 1;
    region[t] = label;
    stack.push_back(static_cast<std::int32_t>(t));
    ball.flood(stack, region, label);
    cavities.emplace_back();
  }
  for (Cavity& c : cavities) c.surface.points = d.points;
  for (std::size_t t = 0; t < region.size(); ++t) {
    if (region[t] <= 0) continue;
    Cavity& c = cavities[static_cast<std::size_t>(region[t] - 1)];
    ++c.cells;
    const double v = simplex_volume<3>(d, t);
    for (int k = 0; k < 3; ++k) {
      double mean = 0;
      for (int j = 0; j < 4; ++j) mean += 0.25 * d.points[d.simplices[t][j]][k];
      c.centroid[k] += v * mean;
    }
    c.cell_volume += v;
    c.vertex_solid_angle += cell_vertex_solid_angle(d, t);
    for (int i = 0; i < 4; ++i) {  // faces where the ball is stopped, normal out of the cavity
      const std::int32_t n = d.neighbours[t][i];
      if (n >= 0 && region[n] == region[t] && ball.passable(t, i)) continue;
      c.surface.triangles.push_back(ball.outward_face(t, i));
    }
  }
  for (Cavity& c : cavities) {
    for (double& x : c.centroid) x /= c.cell_volume;
    measure_surface(c.surface);
  }
  std::stable_sort(cavities.begin(), cavities.end(), [](const Cavity& a, const Cavity& b) { return a.cell_volume > b.cell_volume; });
  return cavities;
}

}  // namespace shockfield::geometry
