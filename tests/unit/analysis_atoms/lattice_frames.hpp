#pragma once
// Test frames: periodic crystals from md::Lattice (LAMMPS `lattice` + `create_atoms box`), with an
// optional homogeneous strain, and the 13-atom icosahedron.
#include <array>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/md/lattice.hpp"

namespace shockfield::analysis::atoms::testing {

/// n×n×n periodic cells of `style` with lattice constant a0, stretched by (1 + strain[d]) along d.
inline AtomFrame crystal(md::LatticeStyle style, double a0, int n, const Vec3& strain = Vec3::Zero()) {
  md::LatticeSpec spec;
  spec.style = style;
  spec.a0 = a0;
  const md::Lattice lattice(spec);
  using geometry::Boundary;
  const auto box = lattice.box({n, n, n}, {Boundary::periodic, Boundary::periodic, Boundary::periodic});
  md::Atoms atoms;
  atoms.mass = {1.0};
  lattice.create_atoms(box, atoms);
  AtomFrame frame;
  frame.box = box;
  const Vec3 stretch = Vec3::Ones() + strain;
  frame.box.hi = box.lo + box.length().cwiseProduct(stretch);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    frame.positions.push_back(box.lo + (atoms.x[i] - box.lo).cwiseProduct(stretch));
    frame.ids.push_back(atoms.id[i]);
    frame.types.push_back(1);
  }
  return frame;
}

/// Hexagonal diamond (lonsdaleite) with in-plane lattice constant a and ideal c = √(8/3) a (bond
/// length √(3/8) a, as cubic diamond of lattice constant √2 a): two hcp lattices shifted by 3c/8
/// along c. Orthohexagonal cells a × √3 a × c of 8 atoms, nx × ny × nz of them, periodic,
/// stretched by (1 + strain[d]) along d.
inline AtomFrame hexagonal_diamond(double a, int nx, int ny, int nz, const Vec3& strain = Vec3::Zero()) {
  const double c = std::sqrt(8.0 / 3.0) * a, b = std::sqrt(3.0) * a;
  // The hexagonal basis (0,0,0), (1/3,2/3,1/2), (0,0,3/8), (1/3,2/3,7/8) in Cartesian axes, and
  // the same shifted by the centring vector (a/2, b/2, 0) of the orthohexagonal cell.
  const std::array<Vec3, 4> basis{Vec3(0, 0, 0), Vec3(0, a / std::sqrt(3.0), c / 2), Vec3(0, 0, 3 * c / 8),
                                  Vec3(0, a / std::sqrt(3.0), 7 * c / 8)};
  AtomFrame frame;
  const Vec3 cell(a, b, c), stretch = Vec3::Ones() + strain;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        for (const Vec3& centring : {Vec3(0, 0, 0), Vec3(a / 2, b / 2, 0)})
          for (const Vec3& p : basis) {
            Vec3 x = Vec3(i * a, j * b, k * c) + p + centring;
            if (x.y() >= (j + 1) * b) x.y() -= b;  // into this cell
            frame.positions.push_back(x.cwiseProduct(stretch));
          }
  frame.box.lo = Vec3::Zero();
  frame.box.hi = Vec3(nx, ny, nz).cwiseProduct(cell).cwiseProduct(stretch);
  for (std::size_t i = 0; i < frame.size(); ++i) {
    frame.ids.push_back(static_cast<std::int64_t>(i + 1));
    frame.types.push_back(1);
  }
  return frame;
}

/// A centre atom (id 1) and the 12 vertices of a regular icosahedron at distance `radius`,
/// in a non-periodic box with 1 Å of room.
inline AtomFrame icosahedron(double radius) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const double s = radius / std::sqrt(1.0 + phi * phi);
  AtomFrame frame;
  frame.positions.push_back(Vec3::Zero());
  for (int a : {-1, 1})
    for (int b : {-1, 1}) {
      frame.positions.emplace_back(0, a * s, b * phi * s);
      frame.positions.emplace_back(a * s, b * phi * s, 0);
      frame.positions.emplace_back(b * phi * s, 0, a * s);
    }
  using geometry::Boundary;
  frame.box.lo = Vec3::Constant(-radius - 1.0);
  frame.box.hi = Vec3::Constant(radius + 1.0);
  frame.box.boundary = {Boundary::fixed, Boundary::fixed, Boundary::fixed};
  for (std::size_t i = 0; i < frame.size(); ++i) {
    frame.ids.push_back(static_cast<std::int64_t>(i + 1));
    frame.types.push_back(1);
  }
  return frame;
}

}  // namespace shockfield::analysis::atoms::testing
