#include "shockfield/geometry/box.hpp"

#include <cmath>
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

void Box::wrap(Vec3& x, std::array<int, 3>& image) const {
  for (int d = 0; d < 3; ++d) {
    if (!periodic(d)) continue;
    const double l = hi[d] - lo[d];
    while (x[d] < lo[d]) { x[d] += l; --image[d]; }
    while (x[d] >= hi[d]) { x[d] -= l; ++image[d]; }
  }
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
