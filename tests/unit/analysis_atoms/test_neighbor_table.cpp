// The shared neighbour table against brute force over periodic images, and its widening for
// atoms short of the requested neighbour count.
#include <gtest/gtest.h>

#include <algorithm>

#include "shockfield/analysis/atoms/neighbor_table.hpp"
#include "unit/analysis_atoms/lattice_frames.hpp"

namespace shockfield::analysis::atoms {
namespace {

// Distances² from atom i to every atom image (shifts of up to 2 box lengths) closer than cutoff,
// sorted: what the table must list.
std::vector<double> brute_force(const AtomFrame& f, std::size_t i, double cutoff) {
  std::vector<double> d2;
  const Vec3 L = f.box.length();
  for (std::size_t j = 0; j < f.size(); ++j)
    for (int a = -2; a <= 2; ++a)
      for (int b = -2; b <= 2; ++b)
        for (int c = -2; c <= 2; ++c) {
          const Vec3 shift(a * L.x(), b * L.y(), c * L.z());
          const double r2 = (f.positions[j] + shift - f.positions[i]).squaredNorm();
          if (r2 > 0 && r2 < cutoff * cutoff) d2.push_back(r2);
        }
  std::sort(d2.begin(), d2.end());
  return d2;
}

TEST(NeighborTable, EqualsBruteForceInABoxSmallerThanTwoCutoffs) {
  // 2×2×2 cells (7.23 Å) with a 4.5 Å cutoff: atoms see several images of the same neighbour.
  AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 2);
  for (std::size_t i = 0; i < frame.size(); ++i) frame.positions[i] += 0.1 * Vec3(std::sin(i), std::cos(3.0 * i), std::sin(7.0 * i));
  const NeighborTable table(frame, {4.5, 0});
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const auto expected = brute_force(frame, i, 4.5);
    const auto list = table.of(i);
    ASSERT_EQ(list.size(), expected.size()) << "atom " << i;
    for (std::size_t k = 0; k < list.size(); ++k)
      EXPECT_NEAR(table.delta(i, list[k]).squaredNorm(), expected[k], 1e-12) << "atom " << i << " entry " << k;
  }
}

TEST(NeighborTable, WidensForAtomsShortOfTheCount) {
  // A dense crystal block and one lone atom 12 Å away, in a fixed box: the mean-density cutoff
  // holds 14 neighbours for the crystal but none for the lone atom, whose search is widened.
  AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 3);
  using geometry::Boundary;
  frame.box.boundary = {Boundary::fixed, Boundary::fixed, Boundary::fixed};
  frame.box.hi.x() += 20.0;
  const Vec3 lone(frame.box.hi.x() - 2.0, 5.0, 5.0);
  frame.positions.push_back(lone);
  frame.ids.push_back(static_cast<std::int64_t>(frame.size()));
  frame.types.push_back(1);
  const NeighborTable table(frame, {0, 14});
  const std::size_t last = frame.size() - 1;
  ASSERT_GE(table.of(last).size(), 14u);
  EXPECT_GT(table.reach(last), table.reach(0));
  // Its 14 nearest are the brute-force 14 nearest (no periodic images: the box is fixed).
  std::vector<double> d2;
  for (std::size_t j = 0; j < last; ++j) d2.push_back((frame.positions[j] - lone).squaredNorm());
  std::sort(d2.begin(), d2.end());
  for (std::size_t k = 0; k < 14; ++k)
    EXPECT_NEAR(table.delta(last, table.of(last)[k]).squaredNorm(), d2[k], 1e-12) << k;
}

TEST(NeighborTable, EmptyFrame) {
  const NeighborTable table(AtomFrame{}, {3.0, 12});
  EXPECT_EQ(table.size(), 0u);
  EXPECT_EQ(table.entries(), 0u);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
