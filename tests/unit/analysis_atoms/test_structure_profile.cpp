// Structure profiles along an axis and the excess energy (analysis/atoms/structure_profile):
// exact counts on a hand-made frame (every atom in one bin, periodic wrapping, end bins for atoms
// outside a shrink-wrapped box), and e0 as the median pe of the crystal atoms.
#include <gtest/gtest.h>

#include "shockfield/analysis/atoms/structure_profile.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

AtomFrame line_frame(geometry::Boundary boundary) {
  AtomFrame f;
  f.box.lo = Vec3(0, 0, 0);
  f.box.hi = Vec3(1, 1, 10);
  f.box.boundary = {geometry::Boundary::periodic, geometry::Boundary::periodic, boundary};
  for (double z : {0.5, 1.5, 2.5, 3.5, 9.9, 10.5, -0.5}) f.positions.emplace_back(0.5, 0.5, z);
  return f;
}

TEST(StructureProfile, CountsPerBin) {
  using S = Structure;
  const std::vector<S> s{S::fcc, S::fcc, S::hcp, S::other, S::fcc, S::hcp, S::bcc};
  const std::vector<double> value{1, 2, 3, 4, 5, 6, 7};
  // Periodic along z: 10.5 wraps to 0.5 (bin 0), −0.5 to 9.5 (bin 3, the last: [7.5, 10)).
  const auto periodic = StructureProfile{2, 2.5}.compute(line_frame(geometry::Boundary::periodic), s, value);
  ASSERT_EQ(periodic.size(), 4u);
  EXPECT_EQ(periodic[0].counts.total, 3u);  // 0.5, 1.5, 10.5 → 0.5
  EXPECT_EQ(periodic[0].counts.of(S::fcc), 2u);
  EXPECT_EQ(periodic[0].counts.of(S::hcp), 1u);
  EXPECT_DOUBLE_EQ(periodic[0].mean_value(), (1 + 2 + 6) / 3.0);
  EXPECT_EQ(periodic[1].counts.total, 2u);  // 2.5, 3.5
  EXPECT_EQ(periodic[2].counts.total, 0u);
  EXPECT_EQ(periodic[3].counts.total, 2u);  // 9.9, −0.5 → 9.5
  EXPECT_DOUBLE_EQ(periodic[3].hi, 10.0);
  // Shrink-wrapped: atoms beyond the faces go to the end bins.
  const auto shrink = StructureProfile{2, 2.5}.compute(line_frame(geometry::Boundary::shrink), s, value);
  EXPECT_EQ(shrink[0].counts.total, 3u);  // 0.5, 1.5, −0.5
  EXPECT_EQ(shrink[3].counts.total, 2u);  // 9.9, 10.5
  EXPECT_EQ(StructureProfile({2, 3.0}).compute(line_frame(geometry::Boundary::periodic), s).size(), 4u);  // ceil(10/3)
}

TEST(StructureProfile, RefusesBadInput) {
  const auto f = line_frame(geometry::Boundary::periodic);
  const std::vector<Structure> s(f.size(), Structure::fcc);
  EXPECT_THROW(StructureProfile({2, 0.0}).compute(f, s), InputError);
  EXPECT_THROW(StructureProfile({2, 1e-6}).compute(f, s), InputError);  // 10^7 bins
  EXPECT_THROW(StructureProfile({3, 1.0}).compute(f, s), InputError);
  EXPECT_THROW(StructureProfile({2, 1.0}).compute(f, {Structure::fcc}), InputError);
}

TEST(ExcessEnergy, MedianOfTheCrystalAtoms) {
  using S = Structure;
  const std::vector<double> pe{-3.54, -3.50, -3.53, -3.0, -3.52};
  const std::vector<S> s{S::fcc, S::hcp, S::fcc, S::other, S::fcc};
  const auto e = excess_energy(pe, s, S::fcc);
  EXPECT_DOUBLE_EQ(e.reference, -3.53);  // median of −3.54, −3.53, −3.52
  EXPECT_NEAR(e.excess[3], 0.53, 1e-12);
  const double e0 = -3.54;
  EXPECT_NEAR(excess_energy(pe, s, S::fcc, &e0).excess[1], 0.04, 1e-12);
  EXPECT_THROW(excess_energy(pe, s, S::bcc), InputError);
  EXPECT_THROW(excess_energy({1.0}, s, S::fcc), InputError);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
