// Bad frames are refused with a message naming the source and the atom.
#include <gtest/gtest.h>

#include <sstream>

#include "unit/analysis_atoms/lattice_frames.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

std::string error_of(const AtomFrame& frame) {
  try {
    validate_frame(frame, "in.dump");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FrameValidation, DuplicateIdNamed) {
  AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 2);
  frame.ids[5] = frame.ids[2];
  EXPECT_NE(error_of(frame).find("atom id 3 appears twice (rows 3 and 6"), std::string::npos) << error_of(frame);
}

TEST(FrameValidation, AtomOutsideFixedBoxNamed) {
  AtomFrame frame = testing::icosahedron(2.5);
  frame.positions[4].y() = 10.0;
  EXPECT_NE(error_of(frame).find("atom id 5 at y = 10 is outside the fixed box"), std::string::npos) << error_of(frame);
}

TEST(FrameValidation, OutsidePeriodicBoxIsItsImage) {
  // An atom one box length away along a periodic axis is the same site: same results.
  AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 3);
  StructureAnalyses a;
  a.cna = ConventionalCna{3.0858};
  a.centro_symmetry = CentroSymmetry{12};
  const auto before = analyze_structure(frame, a);
  frame.positions[7].x() += frame.box.length().x();
  EXPECT_EQ(error_of(frame), "");
  const auto after = analyze_structure(frame, a);
  EXPECT_EQ(after.cna->counts.of(Structure::fcc), frame.size());
  EXPECT_LT(after.centro_symmetry[7], 1e-18);
  EXPECT_EQ(before.cna->structure, after.cna->structure);
}

TEST(FrameValidation, EmptyFrameGivesEmptyResults) {
  AtomFrame frame;
  StructureAnalyses a;
  a.adaptive_cna = AdaptiveCna{};
  const auto r = analyze_structure(frame, a);
  ASSERT_TRUE(r.adaptive_cna);
  EXPECT_EQ(r.adaptive_cna->counts.total, 0u);
}

TEST(FrameValidation, NoAnalysisAskedIsAnError) {
  EXPECT_THROW(analyze_structure(testing::icosahedron(2.5), StructureAnalyses{}), InputError);
}

TEST(CentroSymmetryNeighbors, ParsesNamesAndEvenCounts) {
  EXPECT_EQ(CentroSymmetry::parse_neighbors("fcc", "--csp"), 12);
  EXPECT_EQ(CentroSymmetry::parse_neighbors("bcc", "--csp"), 8);
  EXPECT_EQ(CentroSymmetry::parse_neighbors("16", "--csp"), 16);
  EXPECT_THROW(CentroSymmetry::parse_neighbors("7", "--csp"), InputError);
  EXPECT_THROW(CentroSymmetry::parse_neighbors("hcp", "--csp"), InputError);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
