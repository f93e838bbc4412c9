// The surface of a point set by the method named (point_set_surface.hpp).
#include "shockfield/geometry/point_set_surface.hpp"

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/pivoting_ball.hpp"

namespace shockfield::geometry {

TriangleSurface point_set_surface(const DelaunayDivision<3>& division, const std::string& method, double length) {
  if (method == "delaunay") return rolling_ball_surface(division, length);
  if (method == "pivot") return pivoting_ball_surface(division.points, length);
  if (method == "packing") return packing_sculpting_surface(division, length);
  throw InputError("surface method: expected delaunay, pivot or packing, got '" + method + "'");
}

}  // namespace shockfield::geometry
