// Cubic and hexagonal diamond by the adaptive CNA of second neighbours (Maras et al. 2016, as
// OVITO): every atom of perfect cubic and hexagonal diamond identified at several lattice
// constants and under ±10% homogeneous strain; no diamond found in fcc, hcp, bcc or an
// icosahedron, whose adaptive-CNA types are unchanged beside it; the first- and second-neighbour
// layers of a free surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "unit/analysis_atoms/lattice_frames.hpp"

namespace shockfield::analysis::atoms {
namespace {

using md::LatticeStyle;
using testing::crystal;
using testing::hexagonal_diamond;

DiamondResult diamond_of(const AtomFrame& frame) {
  StructureAnalyses a;
  a.diamond = DiamondCna{};
  return *analyze_structure(frame, a).diamond;
}

const Vec3 kStrains[] = {Vec3(0, 0, 0),     Vec3(0.1, 0, 0),  Vec3(-0.1, 0, 0), Vec3(0, 0.1, 0),
                         Vec3(0, -0.1, 0),  Vec3(0, 0, 0.1),  Vec3(0, 0, -0.1), Vec3(0.05, -0.05, 0.025),
                         Vec3(-0.1, 0.1, 0)};

TEST(DiamondCna, CubicDiamondAtAnyLatticeConstantAndStrain) {
  for (double a0 : {2.0, 3.567, 5.431, 6.489})  // C, Si, α-Sn and a small one
    for (const Vec3& strain : kStrains) {
      const AtomFrame frame = crystal(LatticeStyle::diamond, a0, 3, strain);
      ASSERT_EQ(frame.size(), 216u);
      const DiamondResult r = diamond_of(frame);
      EXPECT_EQ(r.of(DiamondStructure::cubic), frame.size()) << "a0 " << a0 << " strain " << strain.transpose();
      EXPECT_DOUBLE_EQ(r.fraction(DiamondStructure::cubic), 1.0);
    }
}

TEST(DiamondCna, HexagonalDiamondAtAnyLatticeConstantAndStrain) {
  for (double a : {1.5, 2.52, 3.84})
    for (const Vec3& strain : kStrains) {
      const AtomFrame frame = hexagonal_diamond(a, 3, 2, 2, strain);
      ASSERT_EQ(frame.size(), 96u);
      const DiamondResult r = diamond_of(frame);
      EXPECT_EQ(r.of(DiamondStructure::hexagonal), frame.size()) << "a " << a << " strain " << strain.transpose();
    }
}

// The lattice builder's own check: every atom of the hexagonal diamond frame has 4 neighbours at
// the bond length √(3/8) a and the next at more than 1.6 × that (so a wrong builder cannot pass
// the test above by accident of an ill-defined first shell).
TEST(DiamondCna, HexagonalDiamondFrameHasFourBonds) {
  const double a = 2.52;
  const AtomFrame frame = hexagonal_diamond(a, 3, 2, 2);
  const NeighborTable table(frame, {0, 5});
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const auto list = table.of(i);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(table.delta(i, list[k]).norm(), std::sqrt(3.0 / 8.0) * a, 1e-12);
    EXPECT_GT(table.delta(i, list[4]).norm(), 1.6 * std::sqrt(3.0 / 8.0) * a);
  }
}

// Existing structures are unaffected: no diamond atom in fcc, hcp, bcc or the icosahedron, and
// adaptive CNA beside the diamond analysis still finds 100% of each (diamond atoms are "other"
// to it, as in OVITO).
TEST(DiamondCna, OtherStructuresAreNotDiamondAndKeepTheirTypes) {
  const std::map<LatticeStyle, Structure> styles{
      {LatticeStyle::fcc, Structure::fcc}, {LatticeStyle::hcp, Structure::hcp}, {LatticeStyle::bcc, Structure::bcc}};
  for (const auto& [style, structure] : styles)
    for (const Vec3& strain : {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0, -0.1)}) {
      const AtomFrame frame = crystal(style, 3.3, 4, strain);
      StructureAnalyses a;
      a.adaptive_cna = AdaptiveCna{};
      a.diamond = DiamondCna{};
      const auto r = analyze_structure(frame, a);
      EXPECT_EQ(r.diamond->of(DiamondStructure::other), frame.size()) << structure_name(structure);
      EXPECT_EQ(r.adaptive_cna->counts.of(structure), frame.size()) << structure_name(structure);
    }
  const AtomFrame ico = testing::icosahedron(2.5);
  EXPECT_EQ(diamond_of(ico).of(DiamondStructure::other), ico.size());
  StructureAnalyses a;
  a.adaptive_cna = AdaptiveCna{};
  EXPECT_EQ(analyze_structure(crystal(LatticeStyle::diamond, 3.567, 3), a).adaptive_cna->counts.of(Structure::other),
            216u);
}

// A cubic diamond slab with free (001) surfaces: the outermost layer on each side has two bonds
// only, so its atoms and the layer below (whose second neighbours pass through them) are not
// diamond; the layer below is a first neighbour of the diamond interior, the outermost layer a
// second neighbour. Everything else is cubic diamond.
TEST(DiamondCna, FreeSurfaceLayersAreFirstAndSecondNeighbours) {
  const double a0 = 3.567;
  AtomFrame frame = crystal(LatticeStyle::diamond, a0, 4);
  frame.box.boundary[2] = geometry::Boundary::shrink;
  const DiamondResult r = diamond_of(frame);
  double lo = frame.box.hi.z(), hi = frame.box.lo.z();
  for (const Vec3& x : frame.positions) lo = std::min(lo, x.z()), hi = std::max(hi, x.z());
  const double layer = a0 / 4;  // (001) layers of diamond are a/4 apart
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const double depth = std::min(frame.positions[i].z() - lo, hi - frame.positions[i].z());
    const DiamondStructure expected = depth < 0.5 * layer   ? DiamondStructure::cubic_second
                                      : depth < 1.5 * layer ? DiamondStructure::cubic_first
                                                            : DiamondStructure::cubic;
    EXPECT_EQ(r.structure[i], expected) << "atom " << i << " depth " << depth;
  }
  EXPECT_EQ(r.of(DiamondStructure::cubic_second), 64u);  // 32 atoms per (001) layer of 4×4 cells
  EXPECT_EQ(r.of(DiamondStructure::cubic_first), 64u);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
