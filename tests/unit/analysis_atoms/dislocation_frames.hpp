#pragma once
// Test frames with dislocations: oriented Cu crystals displaced by the isotropic Volterra fields of
// straight dislocations (Hirth & Lothe 1982, eqs 3-2 and 3-45, line along the box z axis through
// (x0, y0), cut along θ = ±π), and a crystal with an intrinsic stacking fault.
#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/md/lattice.hpp"

namespace shockfield::analysis::atoms::testing {

inline constexpr double kCuLattice = 3.615;  // Å

/// Cu fcc with the box axes along `orient`, n repeats per axis, the given boundaries.
inline AtomFrame oriented_cu(const std::array<std::array<int, 3>, 3>& orient, const std::array<int, 3>& n,
                             const std::array<geometry::Boundary, 3>& boundary) {
  md::LatticeSpec spec;
  spec.style = md::LatticeStyle::fcc;
  spec.a0 = kCuLattice;
  spec.orient = orient;
  const md::Lattice lattice(spec);
  md::Atoms atoms;
  atoms.mass = {63.546};
  const auto box = lattice.box(n, boundary);
  lattice.create_atoms(box, atoms);
  AtomFrame frame;
  frame.box = box;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    frame.positions.push_back(atoms.x[i]);
    frame.ids.push_back(atoms.id[i]);
    frame.types.push_back(1);
  }
  return frame;
}

inline void fit_box(AtomFrame& frame);

/// Adds the field of a straight dislocation along +z through (x0, y0) with Burgers vector
/// (b_edge, 0, b_screw) in box axes: screw u_z = b_s θ/2π; edge (glide plane y = y0)
///   u_x = b_e/2π [θ + x y / (2(1−ν) r²)],
///   u_y = −b_e/2π [(1−2ν)/(4(1−ν)) ln r² + (x² − y²)/(4(1−ν) r²)].
inline void add_volterra(AtomFrame& frame, double x0, double y0, double b_edge, double b_screw, double nu = 1.0 / 3.0) {
  for (Vec3& p : frame.positions) {
    const double x = p.x() - x0, y = p.y() - y0, r2 = x * x + y * y;
    const double theta = std::atan2(y, x), k = 1.0 / (2 * std::numbers::pi);
    p.x() += b_edge * k * (theta + x * y / (2 * (1 - nu) * r2));
    p.y() -= b_edge * k * ((1 - 2 * nu) / (4 * (1 - nu)) * std::log(r2) + (x * x - y * y) / (4 * (1 - nu) * r2));
    p.z() += b_screw * k * theta;
  }
  fit_box(frame);
}

/// Wraps the atoms into the box along periodic dimensions and shrink-wraps the others.
inline void fit_box(AtomFrame& frame) {
  for (int d = 0; d < 3; ++d) {
    if (frame.box.periodic(d)) {
      const double l = frame.box.length()[d];
      for (Vec3& p : frame.positions) p[d] -= l * std::floor((p[d] - frame.box.lo[d]) / l);
      continue;
    }
    frame.box.lo[d] = frame.box.hi[d] = frame.positions.front()[d];
    for (const Vec3& p : frame.positions) {
      frame.box.lo[d] = std::min(frame.box.lo[d], p[d] - 0.01);
      frame.box.hi[d] = std::max(frame.box.hi[d], p[d] + 0.01);
    }
  }
}

}  // namespace shockfield::analysis::atoms::testing
