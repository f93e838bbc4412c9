#include "shockfield/geometry/region.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace shockfield::geometry {

bool Region::inside(const Vec3& x) const {
  switch (shape) {
    case Shape::block:
      return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
    case Shape::sphere:
      return (x - center).norm() <= radius;
    case Shape::cylinder: {
      Vec3 d = x - center;
      d[axis] = 0.0;
      return d.norm() <= radius && x[axis] >= axial_lo && x[axis] <= axial_hi;
    }
  }
  return false;
}

Region region_from_config(const Config& t) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Region r;
  const std::string shape = t.get_choice("shape", {"block", "sphere", "cylinder"});
  r.side_in = t.get_choice_or("side", {"in", "out"}, "in") == "in";
  if (shape == "block") {
    r.shape = Region::Shape::block;
    for (int d = 0; d < 3; ++d) {  // LAMMPS `region ID block xlo xhi ...`, an absent bound is INF
      const std::string axis(1, "xyz"[d]);
      r.lo[d] = t.get_double_or(axis + "lo", -inf);
      r.hi[d] = t.get_double_or(axis + "hi", inf);
      if (!(r.lo[d] < r.hi[d])) t.fail(axis + "hi", fmt::format("expected {0}hi > {0}lo", axis));
    }
  } else if (shape == "sphere") {
    r.shape = Region::Shape::sphere;
    const auto c = t.get_doubles("center", 3);
    r.center = Vec3(c[0], c[1], c[2]);
    r.radius = t.get_double("radius", Range::positive());
  } else {
    r.shape = Region::Shape::cylinder;
    r.axis = t.get_choice("axis", {"x", "y", "z"})[0] - 'x';
    const auto c = t.get_doubles("center", 2);
    for (int d = 0, k = 0; d < 3; ++d)
      if (d != r.axis) r.center[d] = c[static_cast<std::size_t>(k++)];
    r.radius = t.get_double("radius", Range::positive());
    r.axial_lo = t.get_double_or("lo", -inf);
    r.axial_hi = t.get_double_or("hi", inf);
    if (!(r.axial_lo < r.axial_hi)) t.fail("hi", "expected hi > lo along the cylinder axis");
  }
  return r;
}

}  // namespace shockfield::geometry
