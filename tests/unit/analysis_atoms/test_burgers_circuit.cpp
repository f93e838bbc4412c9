// Burgers vectors by the Frank scheme (analysis/atoms/burgers_circuit): zero in perfect crystal
// and across a stacking fault, a/2[1-10] for Volterra edge and screw dislocations in Cu with the
// FS/RH sign, the two Shockley partials of a dissociated dislocation and their sum.
// The sums are exact integers (units a/6), so the assertions are exact; the step errors are the
// elastic distortion on the circuit, bounded by the reliability threshold 0.25.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dislocation_frames.hpp"
#include "shockfield/analysis/atoms/burgers_circuit.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

using geometry::Boundary;
using testing::kCuLattice;
constexpr Boundary P = Boundary::periodic, S = Boundary::shrink;

// Orientations: edge line along z = [-1-12], glide plane y = (111), b along x = [1-10];
// screw line along z = [1-10] (x = [11-2]).
const std::array<std::array<int, 3>, 3> kEdgeOrient{{{1, -1, 0}, {1, 1, 1}, {-1, -1, 2}}};
const std::array<std::array<int, 3>, 3> kScrewOrient{{{1, 1, -2}, {1, 1, 1}, {1, -1, 0}}};

CrystalFrame crystal_of(const std::array<std::array<int, 3>, 3>& orient) {
  std::array<Vec3i, 3> o;
  for (int d = 0; d < 3; ++d) o[d] = Vec3i(orient[d][0], orient[d][1], orient[d][2]);
  return CrystalFrame::from_orient(o, kCuLattice, "test");
}

BurgersResult around(const AtomFrame& frame, const CrystalFrame& crystal, const Vec3& centre, double radius,
                     const Vec3& axis = Vec3::UnitZ()) {
  const NeighborTable table(frame, {crystal.bond_cutoff(), 0});
  AxisCircuit spec{centre, axis, radius, 1.8, 2.4, crystal.bond_cutoff()};
  return burgers_vector(frame, circuit_around(frame, table, spec), crystal);
}

Vec3 middle(const AtomFrame& f) { return 0.5 * (f.box.lo + f.box.hi); }

TEST(BurgersStepSet, ThirtySixStepsOfOneLength) {
  const auto& set = frank_step_set();
  ASSERT_EQ(set.size(), 36u);  // 12 perfect + 4 planes × 6 out-of-plane mirrors
  for (const Vec3i& v : set) EXPECT_EQ(v.squaredNorm(), 18);
}

TEST(BurgersCircuit, ZeroInPerfectCrystal) {
  const auto frame = testing::oriented_cu(kEdgeOrient, {8, 6, 4}, {P, P, P});
  const auto r = around(frame, crystal_of(kEdgeOrient), middle(frame) + Vec3(0.3, 0.2, 0), 7.0);
  EXPECT_EQ(r.sixths, Vec3i::Zero());
  EXPECT_LT(r.max_step_error, 1e-9);
  EXPECT_EQ(r.kind(), "none");
  EXPECT_GE(r.circuit.size(), 8u);
}

TEST(BurgersCircuit, PerfectScrewFsRh) {
  auto frame = testing::oriented_cu(kScrewOrient, {8, 6, 4}, {S, S, P});
  const Vec3 c = middle(frame) + Vec3(0.31, 0.23, 0);
  const double b = kCuLattice / std::numbers::sqrt2;
  testing::add_volterra(frame, c.x(), c.y(), 0, b);
  const auto crystal = crystal_of(kScrewOrient);
  for (double radius : {6.0, 9.0, 12.0}) {
    const auto r = around(frame, crystal, c, radius);
    EXPECT_EQ(r.sixths, Vec3i(3, -3, 0)) << "radius " << radius;  // +b along ξ = z = [1-10]
    EXPECT_TRUE(r.reliable) << r.max_step_error;
    EXPECT_EQ(r.text(), "[1 -1 0]/2");
    EXPECT_NEAR(r.lab.z(), b, 1e-12);
  }
  // The opposite line sense reverses the circuit and the vector.
  EXPECT_EQ(around(frame, crystal, c, 9.0, -Vec3::UnitZ()).sixths, Vec3i(-3, 3, 0));
}

// A shocked sample is compressed: with the unstrained lattice constant, ±10% homogeneous strain
// along any box axis leaves every step within the reliability bound and b unchanged.
TEST(BurgersCircuit, ScrewUnderTenPercentStrain) {
  const auto crystal = crystal_of(kScrewOrient);
  for (int axis = 0; axis < 3; ++axis)
    for (double strain : {-0.1, 0.1}) {
      auto frame = testing::oriented_cu(kScrewOrient, {8, 6, 4}, {S, S, P});
      const Vec3 c0 = middle(frame) + Vec3(0.31, 0.23, 0);
      testing::add_volterra(frame, c0.x(), c0.y(), 0, kCuLattice / std::numbers::sqrt2);
      Vec3 stretch = Vec3::Ones();
      stretch[axis] += strain;
      for (Vec3& p : frame.positions) p = frame.box.lo + (p - frame.box.lo).cwiseProduct(stretch);
      frame.box.hi = frame.box.lo + frame.box.length().cwiseProduct(stretch);
      testing::fit_box(frame);
      const Vec3 c = frame.box.lo + (c0 - frame.box.lo).cwiseProduct(stretch);
      const auto r = around(frame, crystal, c, 9.0);
      EXPECT_EQ(r.sixths, Vec3i(3, -3, 0)) << "axis " << axis << " strain " << strain;
      EXPECT_TRUE(r.reliable) << "axis " << axis << " strain " << strain << ": " << r.max_step_error;
    }
}

TEST(BurgersCircuit, PerfectEdgeFsRh) {
  auto frame = testing::oriented_cu(kEdgeOrient, {16, 8, 2}, {S, S, P});
  const Vec3 c = middle(frame) + Vec3(0.27, 0.41, 0);
  testing::add_volterra(frame, c.x(), c.y(), kCuLattice / std::numbers::sqrt2, 0);
  const auto crystal = crystal_of(kEdgeOrient);
  for (double radius : {7.0, 10.0, 14.0}) {
    const auto r = around(frame, crystal, c, radius);
    EXPECT_EQ(r.sixths, Vec3i(3, -3, 0)) << "radius " << radius << " error " << r.max_step_error;
    EXPECT_TRUE(r.reliable) << r.max_step_error;
    EXPECT_EQ(r.kind(), "perfect a/2<110>");
  }
}

// A perfect a/2[1-10] dissociated into a/6[2-1-1] + a/6[1-21] on (111), the stacking fault
// between them: each partial alone, and both together (Xu et al. (2015) §3.2.3's check).
TEST(BurgersCircuit, ShockleyPartialsSumToThePerfect) {
  auto frame = testing::oriented_cu(kEdgeOrient, {20, 8, 2}, {S, S, P});
  const Vec3 c = middle(frame) + Vec3(0.27, 0.41, 0);
  const double half = 9.0, be = kCuLattice / (2 * std::numbers::sqrt2), bs = kCuLattice / (2 * std::sqrt(6.0));
  // In box axes (x = [1-10], z = [-1-12]): b1 = a/6[2-1-1] = (a/2√2, 0, −a/2√6) on the left,
  // b2 = a/6[1-21] = (a/2√2, 0, a/2√6) on the right. Both cuts run to −x, so between the cores
  // the jump is b2 alone: an intrinsic stacking fault (with b1 there instead, atoms would sit on
  // top of each other across the plane and the steps would not fit the step set).
  testing::add_volterra(frame, c.x() - half, c.y(), be, -bs);
  testing::add_volterra(frame, c.x() + half, c.y(), be, bs);
  const auto crystal = crystal_of(kEdgeOrient);
  const auto left = around(frame, crystal, c - Vec3(half, 0, 0), 5.5);
  const auto right = around(frame, crystal, c + Vec3(half, 0, 0), 5.5);
  const auto both = around(frame, crystal, c, 16.0);
  EXPECT_EQ(left.sixths, Vec3i(2, -1, -1)) << left.max_step_error;
  EXPECT_EQ(right.sixths, Vec3i(1, -2, 1)) << right.max_step_error;
  EXPECT_EQ(both.sixths, Vec3i(3, -3, 0)) << both.max_step_error;
  EXPECT_EQ(left.kind(), "Shockley a/6<112>");
  EXPECT_EQ(left.sixths + right.sixths, both.sixths);
  for (const auto* r : {&left, &right, &both}) EXPECT_TRUE(r->reliable) << r->max_step_error;
}

// The crystal above a (111) plane slipped by a/6[1-21]: an intrinsic stacking fault without a
// bounding partial. A circuit crossing it twice closes (b = 0, every step on the step set, through
// the mirrored steps). Slipped by a/6[2-1-1] instead, the layers sit on top of each other
// (not a stacking fault): the crossing steps fit no vector and the result is flagged unreliable.
TEST(BurgersCircuit, ZeroAcrossAStackingFault) {
  const auto crystal = crystal_of(kEdgeOrient);
  for (const double screw : {1.0, -1.0}) {
    auto frame = testing::oriented_cu(kEdgeOrient, {10, 8, 4}, {P, S, P});
    const Vec3 c = middle(frame);
    double layer = frame.positions.front().y();  // the atomic layer nearest the middle
    for (const Vec3& p : frame.positions)
      if (std::abs(p.y() - c.y()) < std::abs(layer - c.y())) layer = p.y();
    const double plane = layer + kCuLattice / (2 * std::sqrt(3.0));
    const Vec3 slip(kCuLattice / (2 * std::numbers::sqrt2), 0, screw * kCuLattice / (2 * std::sqrt(6.0)));
    for (Vec3& p : frame.positions)
      if (p.y() > plane) p += slip;
    testing::fit_box(frame);
    const auto r = around(frame, crystal, Vec3(c.x() + 0.3, plane, c.z()), 7.0);
    if (screw > 0) {
      EXPECT_EQ(r.sixths, Vec3i::Zero());
      EXPECT_LT(r.max_step_error, 1e-9);
    } else {
      EXPECT_FALSE(r.reliable) << r.max_step_error;
    }
  }
}

TEST(BurgersCircuit, RefusesBadInput) {
  const auto frame = testing::oriented_cu(kEdgeOrient, {4, 4, 4}, {P, P, P});
  const auto crystal = crystal_of(kEdgeOrient);
  EXPECT_THROW(CrystalFrame::from_orient({Vec3i(1, 0, 0), Vec3i(1, 1, 0), Vec3i(0, 0, 1)}, 3.6, "t"), InputError);
  EXPECT_THROW(CrystalFrame::from_orient({Vec3i(1, 0, 0), Vec3i(0, 1, 0), Vec3i(0, 0, -1)}, 3.6, "t"), InputError);
  EXPECT_THROW(CrystalFrame::from_orient({Vec3i(1, 0, 0), Vec3i(0, 1, 0), Vec3i(0, 0, 1)}, 0, "t"), InputError);
  EXPECT_THROW(circuit_of_ids(frame, {1, 2}), InputError);
  EXPECT_THROW(circuit_of_ids(frame, {1, 2, 999999}), InputError);
  // Atoms 1, 2, 3 are not all neighbours of each other: a step is too long.
  const std::size_t far = frame.size() / 2;
  EXPECT_THROW(burgers_vector(frame, {0, 1, far}, crystal), InputError);
  const NeighborTable table(frame, {crystal.bond_cutoff(), 0});
  EXPECT_THROW(circuit_around(frame, table, {middle(frame), Vec3::Zero(), 5, 1, 1, crystal.bond_cutoff()}), InputError);
  EXPECT_THROW(circuit_around(frame, table, {middle(frame), Vec3::UnitZ(), 5, 0.01, 0.01, crystal.bond_cutoff()}),
               InputError);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
