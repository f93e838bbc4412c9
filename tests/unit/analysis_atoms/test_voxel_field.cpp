// Atoms to a grid field (analysis/atoms/voxel_field.hpp): cloud-in-cell fractions, smoothing,
// the grid and its stretch.
#include <gtest/gtest.h>

#include <numeric>

#include "lattice_frames.hpp"
#include "shockfield/analysis/atoms/voxel_field.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

// Every atom selected: fraction 1 on every node; cloud-in-cell conserves the atoms, so the
// density summed over the nodes times h³ is the atom count (to round-off), with or without the
// (normalised, periodic) smoothing.
TEST(VoxelField, UniformSelectionAndConservedAtoms) {
  const AtomFrame f = testing::crystal(md::LatticeStyle::fcc, 3.615, 4);
  for (double sigma : {0.0, 2.0}) {
    const VoxelField g = voxel_fraction(f, std::vector<bool>(f.size(), true), {1.3, sigma});
    for (double v : g.fraction) ASSERT_DOUBLE_EQ(v, g.empty_nodes ? v : 1.0);
    const double atoms = std::accumulate(g.density.begin(), g.density.end(), 0.0) * 1.3 * 1.3 * 1.3;
    EXPECT_NEAR(atoms, static_cast<double>(f.size()), 1e-9 * static_cast<double>(f.size())) << sigma;
    EXPECT_EQ(g.selected, f.size());
  }
}

// Grid: n = round(L/h) nodes per periodic axis, the stretch n h / L; a non-periodic axis has
// walls on its first and last node, n = round(L/h) + 1.
TEST(VoxelField, GridAndStretch) {
  AtomFrame f = testing::crystal(md::LatticeStyle::fcc, 3.615, 4);  // L = 14.46 Å
  const VoxelField g = voxel_fraction(f, std::vector<bool>(f.size(), false), {1.0, 0.0});
  EXPECT_EQ(g.n[0], 14u);
  EXPECT_NEAR(g.stretch[0], 14.0 / 14.46, 1e-12);
  f.box.boundary[2] = geometry::Boundary::shrink;
  EXPECT_EQ(voxel_fraction(f, std::vector<bool>(f.size(), false), {1.0, 0.0}).n[2], 15u);
  EXPECT_THROW(voxel_fraction(f, std::vector<bool>(f.size(), false), {20.0, 0.0}), InputError);
  EXPECT_THROW(voxel_fraction(f, std::vector<bool>(f.size(), false), {1.0, -1.0}), InputError);
}

// The atoms in the lower half along x selected: smoothed fraction 1 deep in that half, 0 deep in
// the other, and 1/2 at the two interfaces (x = 0 ≡ L and x = L/2, by symmetry).
TEST(VoxelField, HalfSpaceFraction) {
  const AtomFrame f = testing::crystal(md::LatticeStyle::fcc, 3.615, 8);  // L = 28.92 Å
  std::vector<bool> sel(f.size());
  const double L = f.box.length().x();
  for (std::size_t i = 0; i < f.size(); ++i) sel[i] = f.positions[i].x() - f.box.lo.x() < 0.5 * L - 0.1;
  const VoxelField g = voxel_fraction(f, sel, {L / 24, 1.5});
  auto at = [&](std::size_t i) { return g.fraction[g.n[0] * (g.n[1] * 3 + 5) + i]; };
  EXPECT_NEAR(at(6), 1.0, 1e-3);
  EXPECT_NEAR(at(18), 0.0, 1e-3);
  EXPECT_NEAR(0.5 * (at(11) + at(12)), 0.5, 0.1);  // the interface between 11.5 and 12 nodes
  EXPECT_EQ(g.empty_nodes, 0u);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
