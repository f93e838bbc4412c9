#include "shockfield/geometry/box.hpp"

#include <cmath>
#include <limits>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::geometry {

Boundary parse_boundary(const std::string& code, const std::string& what) {
  if (code == "p") return Boundary::periodic;
  if (code == "f") return Boundary::fixed;
  if (code == "s") return Boundary::shrink;
  throw InputError(fmt::format("{}: boundary '{}' is not one of p (periodic), f (fixed), s (shrink-wrapped)", what, code));
}

char boundary_code(Boundary b) {
  switch (b) {
    case Boundary::periodic: return 'p';
    case Boundary::fixed: return 'f';
    case Boundary::shrink: return 's';
  }
  return '?';
}

bool Box::contains(const Vec3& x) const {
  for (int d = 0; d < 3; ++d)
    if (x[d] < lo[d] || x[d] >= hi[d]) return false;
  return true;
}

bool Box::try_wrap(Vec3& x, std::array<int, 3>& image) const {
  Vec3 y = x;
  std::array<int, 3> n = image;
  for (int d = 0; d < 3; ++d) {
    if (!periodic(d)) continue;
    if (!std::isfinite(y[d])) return false;
    if (y[d] >= lo[d] && y[d] < hi[d]) continue;
    const double l = hi[d] - lo[d];
    const double shifts = std::floor((y[d] - lo[d]) / l);
    const double total = shifts + n[d];
    if (!(std::abs(total) < std::numeric_limits<int>::max())) return false;  // room for +-1 below
    y[d] -= shifts * l;
    n[d] = static_cast<int>(total);
    // Round-off of the subtraction can leave y one step outside; a point that still is outside
    // (y so far away that l is below its precision) cannot be placed.
    if (y[d] < lo[d]) y[d] += l, --n[d];
    if (y[d] >= hi[d]) y[d] -= l, ++n[d];
    if (!(y[d] >= lo[d] && y[d] < hi[d])) return false;
  }
  x = y;
  image = n;
  return true;
}

void Box::wrap(Vec3& x, std::array<int, 3>& image) const {
  if (try_wrap(x, image)) return;
  throw RunError(fmt::format("a position ({}, {}, {}) cannot be wrapped into the periodic box "
                             "[{}, {}] x [{}, {}] x [{}, {}]: it is not finite or more than 2^31 "
                             "box lengths away (the run blew up, or the box is far too small)",
                             x.x(), x.y(), x.z(), lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()));
}

Vec3 Box::minimum_image(Vec3 d) const {
  for (int k = 0; k < 3; ++k) {
    if (!periodic(k)) continue;
    const double l = hi[k] - lo[k];
    d[k] -= l * std::round(d[k] / l);
  }
  return d;
}

std::string Box::boundary_codes() const {
  return {boundary_code(boundary[0]), boundary_code(boundary[1]), boundary_code(boundary[2])};
}

}  // namespace shockfield::geometry
