#include "shockfield/md/lattice.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/shrink_wrap.hpp"

namespace shockfield::md {
namespace {

// Unit-cell vectors (columns, units of a0) and basis fractions of LAMMPS lattice.cpp.
struct CellDef {
  Vec3 edges;  // the conventional cells are orthogonal: a1 = edges.x ex, a2 = edges.y ey, ...
  std::vector<Vec3> basis;
};

CellDef cell_def(LatticeStyle style, double c_over_a) {
  const std::vector<Vec3> fcc{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  switch (style) {
    case LatticeStyle::sc: return {Vec3::Ones(), {{0, 0, 0}}};
    case LatticeStyle::bcc: return {Vec3::Ones(), {{0, 0, 0}, {0.5, 0.5, 0.5}}};
    case LatticeStyle::fcc: return {Vec3::Ones(), fcc};
    case LatticeStyle::hcp:
      return {Vec3(1, std::sqrt(3.0), c_over_a),
              {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 5.0 / 6.0, 0.5}, {0, 1.0 / 3.0, 0.5}}};
    case LatticeStyle::diamond: {
      std::vector<Vec3> b{{0, 0, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}, {0.5, 0.5, 0}};
      for (int i = 0; i < 4; ++i) b.push_back(b[i] + Vec3(0.25, 0.25, 0.25));
      return {Vec3::Ones(), b};
    }
  }
  return {};
}

constexpr double tolerance = 1e-8;

bool near_integer(double v) { return std::abs(v - std::round(v)) < tolerance; }

// True when shifting every basis atom by the fractional vector f lands on a basis atom.
bool is_translation(const std::vector<Vec3>& basis, const Vec3& f) {
  for (const Vec3& b : basis) {
    bool found = false;
    for (const Vec3& c : basis) {
      const Vec3 d = b + f - c;
      if (near_integer(d.x()) && near_integer(d.y()) && near_integer(d.z())) { found = true; break; }
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace

const std::vector<std::string>& lattice_style_names() {
  static const std::vector<std::string> names{"sc", "bcc", "fcc", "hcp", "diamond"};
  return names;
}

LatticeStyle parse_lattice_style(const std::string& name, const std::string& what) {
  const auto& names = lattice_style_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<LatticeStyle>(i);
  throw InputError(fmt::format("{}: lattice style '{}' is not one of {}", what, name, fmt::join(names, ", ")));
}

Lattice::Lattice(const LatticeSpec& spec) : spec_(spec) {
  if (!(spec.a0 > 0) || !std::isfinite(spec.a0))
    throw InputError(fmt::format("lattice constant a0 must be > 0, got {}", spec.a0));
  if (spec.c_over_a && spec.style != LatticeStyle::hcp)
    throw InputError("c/a is only used by the hcp lattice");
  if (spec.c_over_a && !(*spec.c_over_a > 0))
    throw InputError(fmt::format("c/a must be > 0, got {}", *spec.c_over_a));
  const CellDef def = cell_def(spec.style, spec.c_over_a.value_or(std::sqrt(8.0 / 3.0)));
  basis_ = def.basis;
  cell_ = (spec.a0 * def.edges).asDiagonal();
  if (!spec.basis_types.empty() && spec.basis_types.size() != basis_.size())
    throw InputError(fmt::format("{} basis types given, the {} lattice has {} basis atoms",
                                 spec.basis_types.size(), lattice_style_names()[static_cast<int>(spec.style)], basis_.size()));
  for (int t : spec.basis_types)
    if (t < 0) throw InputError(fmt::format("basis type {} must be >= 1", t + 1));

  // LAMMPS Lattice::Lattice: "Lattice orient vectors are not orthogonal / not right-handed".
  Eigen::Matrix3i o;
  for (int d = 0; d < 3; ++d) o.row(d) << spec.orient[d][0], spec.orient[d][1], spec.orient[d][2];
  const auto desc = [&] {
    return fmt::format("orient x=[{}] y=[{}] z=[{}]", fmt::join(spec.orient[0], ","),
                       fmt::join(spec.orient[1], ","), fmt::join(spec.orient[2], ","));
  };
  for (int d = 0; d < 3; ++d)
    if (o.row(d).squaredNorm() == 0) throw InputError(fmt::format("lattice {}: zero vector", desc()));
  if (o.row(0).dot(o.row(1)) != 0 || o.row(1).dot(o.row(2)) != 0 || o.row(0).dot(o.row(2)) != 0)
    throw InputError(fmt::format("lattice {}: the vectors are not orthogonal", desc()));
  const Eigen::Vector3i xy = Eigen::Vector3i(o.row(0)).cross(Eigen::Vector3i(o.row(1)));
  if (xy.dot(Eigen::Vector3i(o.row(2))) <= 0)
    throw InputError(fmt::format("lattice {}: the vectors are not right-handed ((x × y)·z must be > 0)", desc()));
  for (int d = 0; d < 3; ++d) rotate_.row(d) = o.row(d).cast<double>().normalized();

  // Periodic repeat: the shortest t with t·u a crystal translation, searched as k/(12·|w_max|)
  // (12 covers the basis fractions ½ ⅓ ¼ ⅙ of every style) for up to 50 conventional cells.
  const Mat3 to_fraction = cell_.inverse();
  for (int d = 0; d < 3; ++d) {
    const Vec3 w = to_fraction * rotate_.row(d).transpose();
    const double step = 1.0 / (12.0 * w.cwiseAbs().maxCoeff());
    repeat_[d] = 0;
    for (int k = 1; k <= 12 * 50 && repeat_[d] == 0; ++k)
      if (is_translation(basis_, k * step * w)) repeat_[d] = k * step;
    if (repeat_[d] == 0)
      throw InputError(fmt::format("lattice {}: the crystal does not repeat along {} within 50 cells",
                                   desc(), "xyz"[d]));
  }
}

geometry::Box Lattice::box(const std::array<int, 3>& n, const std::array<geometry::Boundary, 3>& boundary) const {
  geometry::Box b;
  for (int d = 0; d < 3; ++d) {
    if (n[d] < 1) throw InputError(fmt::format("lattice repeat count along {} must be >= 1, got {}", "xyz"[d], n[d]));
    b.lo[d] = 0.0;
    b.hi[d] = n[d] * repeat_[d];
  }
  b.boundary = boundary;
  return b;
}

Vec3 Lattice::site(const std::array<long long, 3>& cell, std::size_t b) const {
  const Vec3 f(static_cast<double>(cell[0]) + basis_[b].x(), static_cast<double>(cell[1]) + basis_[b].y(),
               static_cast<double>(cell[2]) + basis_[b].z());
  return rotate_ * (cell_ * f);
}

std::size_t Lattice::create_atoms(const geometry::Box& box, Atoms& atoms) const {
  std::int64_t tag = atoms.max_id();
  const std::size_t before = atoms.nlocal;
  for_each_site(box, [&](const Vec3& x, int type) { atoms.add(x, type, ++tag); });
  return atoms.nlocal - before;
}

void Lattice::for_each_site(const geometry::Box& box, const std::function<void(const Vec3&, int)>& visit) const {
  // Range of conventional cells covering the box: its corners in fractional lattice coordinates.
  const Mat3 to_fraction = cell_.inverse() * rotate_.transpose();
  Vec3 fmin = Vec3::Constant(INFINITY), fmax = Vec3::Constant(-INFINITY);
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner = box.triclinic() ? box.from_fractional(Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1))
                                        : Vec3(c & 1 ? box.hi.x() : box.lo.x(), c & 2 ? box.hi.y() : box.lo.y(),
                                               c & 4 ? box.hi.z() : box.lo.z());
    const Vec3 f = to_fraction * corner;
    fmin = fmin.cwiseMin(f);
    fmax = fmax.cwiseMax(f);
  }
  // The half-open range a site must lie in, per axis (CreateAtoms::add_lattice; see lattice.hpp).
  // A triclinic cell compares fractional coordinates, ε = 10⁻⁶ in them (LAMMPS: EPSILON in lamda
  // units); it has no shrink-wrapped dimension (Box::check_tilt).
  const bool triclinic = box.triclinic();
  const Vec3 eps = triclinic ? Vec3::Constant(1e-6) : Vec3(1e-6 * box.length());
  const Vec3 small = geometry::shrink_margin(box);
  const Vec3 box_lo = triclinic ? Vec3::Zero() : box.lo, box_hi = triclinic ? Vec3::Ones() : box.hi;
  Vec3 lo_bound, hi_bound;
  for (int d = 0; d < 3; ++d) {
    switch (box.boundary[static_cast<std::size_t>(d)]) {
      case geometry::Boundary::periodic: lo_bound[d] = box_lo[d] - eps[d], hi_bound[d] = box_hi[d] - 2 * eps[d]; break;
      case geometry::Boundary::fixed: lo_bound[d] = box_lo[d] - eps[d], hi_bound[d] = box_hi[d] - eps[d]; break;
      case geometry::Boundary::shrink: lo_bound[d] = box.lo[d] - small[d], hi_bound[d] = box.hi[d] + small[d]; break;
    }
  }
  std::array<long long, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    lo[d] = static_cast<long long>(std::floor(fmin[d])) - 1;
    hi[d] = static_cast<long long>(std::ceil(fmax[d])) + 1;
  }
  std::array<long long, 3> cell{};
  for (cell[2] = lo[2]; cell[2] <= hi[2]; ++cell[2])
    for (cell[1] = lo[1]; cell[1] <= hi[1]; ++cell[1])
      for (cell[0] = lo[0]; cell[0] <= hi[0]; ++cell[0])
        for (std::size_t b = 0; b < basis_.size(); ++b) {
          Vec3 x = site(cell, b);
          const Vec3 s = triclinic ? box.to_fractional(x) : x;
          bool inside = true;
          for (int d = 0; d < 3 && inside; ++d)
            inside = s[d] >= lo_bound[d] && s[d] < hi_bound[d];
          if (!inside) continue;
          std::array<int, 3> image{0, 0, 0};
          box.wrap(x, image);
          for (int d = 0; d < 3 && !triclinic; ++d)  // a site a round-off below a fixed lo face is on it
            if (box.boundary[static_cast<std::size_t>(d)] == geometry::Boundary::fixed) x[d] = std::max(x[d], box.lo[d]);
          visit(x, spec_.basis_types.empty() ? 0 : spec_.basis_types[b]);
        }
}

}  // namespace shockfield::md
