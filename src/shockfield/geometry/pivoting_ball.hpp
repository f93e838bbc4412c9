#pragma once
// The rolling-ball surface by the pivoting algorithm of Xu et al. (2015) §3.2.3, steps I–III, on
// the SHT searchers (pivot_searches.hpp):
//   I   seed: P1 = the point of largest x (a minimum search of −x; the paper's MS2 from a centre
//       P0 outside the points, with P0 at +∞ along x), the ball of radius r on P1 at +x (empty:
//       no point has a larger x) turned by MS3 about the z axis through P1 to meet P2, then by
//       MS3 about P1P2 to meet P3; the triangle P1P2P3, normal towards the ball, and its three
//       edges in the segment tree (the front);
//   II  take an edge AB of triangle ABC off the front; MS1: the ball on ABC turned about AB meets
//       P; triangle BAP; for each of its edges PB and AP (CS1) remove the front's reversed twin,
//       else add the edge to the front;
//   III repeat until the front is empty.
// The triangles are kept in a list (the paper's triangle tree tt is not needed: no search asks for
// triangles). The result is the component of the surface the seed is on, with normals towards
// the ball (outwards).
#include <vector>

#include "shockfield/geometry/rolling_ball.hpp"
#include "shockfield/geometry/vec3.hpp"

namespace shockfield::geometry {

/// The surface the ball of radius `radius` touches, pivoted from the seed of step I; of equal
/// points only the first is used. Throws InputError for fewer than 3 distinct points, a non-finite
/// coordinate or radius, when the seed cannot be placed (the ball meets fewer than three points),
/// and when the surface does not close (an edge about which the ball meets no point, a triangle
/// made twice, or an edge on more than two triangles: the radius is too small or too large for the
/// sampling).
TriangleSurface pivoting_ball_surface(const std::vector<Point3>& points, double radius);

}  // namespace shockfield::geometry
