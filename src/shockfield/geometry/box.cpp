#include "shockfield/geometry/box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <Eigen/Geometry>
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

Vec3 Box::edge(int d) const {
  const Vec3 l = length();
  if (d == 0) return {l.x(), 0, 0};
  if (d == 1) return {tilt.x(), l.y(), 0};
  return {tilt.y(), tilt.z(), l.z()};
}

Mat3 Box::cell() const {
  Mat3 h;
  h << edge(0), edge(1), edge(2);
  return h;
}

Vec3 Box::lattice_shift(const std::array<int, 3>& n) const {
  const Vec3 l = length();
  return {n[0] * l.x() + n[1] * tilt.x() + n[2] * tilt.y(), n[1] * l.y() + n[2] * tilt.z(), n[2] * l.z()};
}

// h is upper triangular, so h^-1 (x - lo) by back substitution (z, then y, then x).
Vec3 Box::to_fractional(const Vec3& x) const { return fractional_vector(x - lo); }

Vec3 Box::fractional_vector(const Vec3& r) const {
  const Vec3 l = length();
  const double sz = r.z() / l.z();
  const double sy = (r.y() - tilt.z() * sz) / l.y();
  const double sx = (r.x() - tilt.x() * sy - tilt.y() * sz) / l.x();
  return {sx, sy, sz};
}

Vec3 Box::from_fractional(const Vec3& s) const {
  const Vec3 l = length();
  return lo + Vec3(l.x() * s.x() + tilt.x() * s.y() + tilt.y() * s.z(), l.y() * s.y() + tilt.z() * s.z(), l.z() * s.z());
}

// Face distance along edge d = V / |area of the face spanned by the other two edges| = 1 / |row d
// of h^-1| (LAMMPS Comm::setup's length0/1/2 for triclinic ghost cutoffs).
Vec3 Box::face_distances() const {
  const Vec3 a = edge(0), b = edge(1), c = edge(2);
  const double v = volume();
  return {v / b.cross(c).norm(), v / c.cross(a).norm(), v / a.cross(b).norm()};
}

Vec3 Box::bound_lo() const {
  const double xy = tilt.x(), xz = tilt.y(), yz = tilt.z();
  return lo + Vec3(std::min({0.0, xy, xz, xy + xz}), std::min(0.0, yz), 0);
}

Vec3 Box::bound_hi() const {
  const double xy = tilt.x(), xz = tilt.y(), yz = tilt.z();
  return hi + Vec3(std::max({0.0, xy, xz, xy + xz}), std::max(0.0, yz), 0);
}

Box box_from_bounds(const Vec3& bound_lo, const Vec3& bound_hi, const Vec3& tilt,
                    const std::array<Boundary, 3>& boundary) {
  const double xy = tilt.x(), xz = tilt.y(), yz = tilt.z();
  Box box;
  box.tilt = tilt;
  box.boundary = boundary;
  box.lo = bound_lo - Vec3(std::min({0.0, xy, xz, xy + xz}), std::min(0.0, yz), 0);
  box.hi = bound_hi - Vec3(std::max({0.0, xy, xz, xy + xz}), std::max(0.0, yz), 0);
  return box;
}

void Box::check_tilt(const std::string& where) const {
  if (!triclinic()) return;
  const Vec3 l = length();
  static const char* names[3] = {"xy", "xz", "yz"};
  const double edge_length[3] = {l.x(), l.x(), l.y()};
  const int skewed[3] = {1, 2, 2};  // the dimension whose edge each factor tilts
  for (int k = 0; k < 3; ++k) {
    if (tilt[k] != 0 && !periodic(skewed[k]))
      throw InputError(fmt::format("{}: tilt {} = {} needs a periodic {} boundary (LAMMPS: a triclinic box "
                                   "must be periodic in its skewed dimensions), got '{}'",
                                   where, names[k], tilt[k], "xyz"[skewed[k]], boundary_codes()));
    if (!(std::abs(tilt[k]) <= 0.5 * edge_length[k]))
      throw InputError(fmt::format("{}: tilt {} = {} is beyond LAMMPS's limit of half the {} edge ({}): "
                                   "a restricted triclinic cell needs |{}| <= {} / 2 (flip the cell to "
                                   "the equivalent one with the smaller tilt)",
                                   where, names[k], tilt[k], k < 2 ? "x" : "y", edge_length[k], names[k],
                                   k < 2 ? "lx" : "ly"));
  }
  for (int d = 0; d < 3; ++d)
    if (boundary[d] == Boundary::shrink)
      throw InputError(fmt::format("{}: a triclinic box (tilt {} {} {}) with a shrink-wrapped boundary ('{}') "
                                   "is not supported: use p or f", where, tilt[0], tilt[1], tilt[2], boundary_codes()));
}

CellFlip Box::flip_beyond(double fraction) const {
  CellFlip f;
  const Vec3 l = length();
  double xz = tilt.y();
  if (periodic(1) && std::abs(tilt.z()) > fraction * l.y()) {
    f.p = tilt.z() > 0 ? -1 : 1;
    xz += f.p * tilt.x();
  }
  if (periodic(0) && std::abs(xz) > fraction * l.x()) f.n = xz > 0 ? -1 : 1;
  if (periodic(0) && std::abs(tilt.x()) > fraction * l.x()) f.m = tilt.x() > 0 ? -1 : 1;
  return f;
}

void Box::apply_flip(const CellFlip& f) {
  const Vec3 l = length();
  // LAMMPS's order: yz (moving xz by the old xy), then xz, then xy.
  tilt.z() += f.p * l.y();
  tilt.y() += f.p * tilt.x();
  tilt.y() += f.n * l.x();
  tilt.x() += f.m * l.x();
}

std::array<int, 3> flipped_image(const std::array<int, 3>& image, const CellFlip& f) {
  const int b = image[1] - f.p * image[2];
  return {image[0] - f.m * b - f.n * image[2], b, image[2]};
}

void require_orthogonal(const Box& box, const std::string& what) {
  if (box.triclinic())
    throw InputError(fmt::format("{} needs an orthogonal box; this one is triclinic (tilt xy xz yz = {} {} {})", what,
                                 box.tilt[0], box.tilt[1], box.tilt[2]));
}

bool Box::contains(const Vec3& x) const {
  if (triclinic()) {
    const Vec3 s = to_fractional(x);
    return s.minCoeff() >= 0 && s.maxCoeff() < 1;
  }
  for (int d = 0; d < 3; ++d)
    if (x[d] < lo[d] || x[d] >= hi[d]) return false;
  return true;
}

// The triclinic wrap subtracts whole edge vectors, c then b then a, each by the floor of the
// fractional coordinate it changes (LAMMPS Domain::remap works in lamda coordinates instead; the
// positions agree to round-off).
bool Box::try_wrap_triclinic(Vec3& x, std::array<int, 3>& image) const {
  if (!x.allFinite()) return false;
  Vec3 y = x;
  std::array<int, 3> n = image;
  for (int d = 2; d >= 0; --d) {  // edge d changes fractional coordinate d only
    if (!periodic(d)) continue;
    const double s = to_fractional(y)[d];
    if (s >= 0 && s < 1) continue;
    const double shifts = std::floor(s);
    const double total = shifts + n[d];
    if (!(std::abs(total) < std::numeric_limits<int>::max())) return false;  // room for +-1 below
    y -= shifts * edge(d);
    n[d] = static_cast<int>(total);
    const double t = to_fractional(y)[d];  // round-off can leave y one step outside
    if (t < 0) y += edge(d), --n[d];
    if (t >= 1) y -= edge(d), ++n[d];
    double u = to_fractional(y)[d];
    if (u >= 1 && u < 1 + 1e-12) {  // on the hi face by round-off both ways: to the lo face
      y -= edge(d);
      ++n[d];
      u = to_fractional(y)[d];
    }
    if (u < 0 && u > -1e-12) {
      // Still below the lo face by round-off: a point a few ulps from the face at x = lo + (tilt
      // terms) can have no representable position inside; as LAMMPS's Domain::remap clamps lamda
      // to lo, move it onto the face (by ~1e-12 of an edge at most).
      y -= u * edge(d);
      u = std::max(to_fractional(y)[d], 0.0);
    }
    if (!(u >= 0 && u < 1)) return false;
  }
  x = y;
  image = n;
  return true;
}

bool Box::try_wrap(Vec3& x, std::array<int, 3>& image) const {
  if (triclinic()) return try_wrap_triclinic(x, image);
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
  if (triclinic()) {
    for (int k = 2; k >= 0; --k) {
      if (!periodic(k)) continue;
      d -= std::round(fractional_vector(d)[k]) * edge(k);
    }
    return d;
  }
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
