#pragma once
// The surface of a 3D point set by one of the three methods of Xu et al. (2015) §3.2.3 that
// `shockfield analyze geometry --surface-method` offers and shockfield.analysis.surface calls.
#include <string>

#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/rolling_ball.hpp"

namespace shockfield::geometry {

/// "delaunay": rolling_ball_surface (every component a ball of radius `length` touches from
/// outside); "pivot": pivoting_ball_surface (the component on the point of largest x);
/// "packing": packing_sculpting_surface to the depth `length`. InputError for another method
/// and the InputErrors of those functions.
TriangleSurface point_set_surface(const DelaunayDivision<3>& division, const std::string& method, double length);

}  // namespace shockfield::geometry
