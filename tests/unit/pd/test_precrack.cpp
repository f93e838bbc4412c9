// Pre-cracks (precrack.hpp): the bonds a crack cuts on small lattices, counted by hand and by an
// independent floating-point intersection (parametric segment/segment in 2D, segment/plane and
// the crack's own coordinates in 3D, on generic cracks where no bond touches the crack exactly),
// and the damage the cut bonds leave along the crack of a plate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/LU>

#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/precrack.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

double cross2(const Vec3& a, const Vec3& b) { return a.x() * b.y() - a.y() * b.x(); }

// Segment a–b against crack p–q: a + s(b − a) = p + t(q − p) with 0 < s < 1, 0 <= t <= 1.
bool segments_cross(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q) {
  const Vec3 r = b - a, e = q - p;
  const double d = cross2(r, e);
  if (d == 0.0) return false;
  const double s = cross2(p - a, e) / d, t = cross2(p - a, r) / d;
  return s > 0.0 && s < 1.0 && t >= 0.0 && t <= 1.0;
}

// Segment a–b against the parallelogram o + u·e1 + w·e2, 0 <= u, w <= 1 (solved as a 3×3 system).
bool crosses_parallelogram(const Vec3& a, const Vec3& b, const Vec3& o, const Vec3& e1, const Vec3& e2) {
  Mat3 m;
  m.col(0) = b - a, m.col(1) = -e1, m.col(2) = -e2;
  const Vec3 x = m.fullPivLu().solve(o - a);
  return x[0] > 0.0 && x[0] < 1.0 && x[1] >= 0.0 && x[1] <= 1.0 && x[2] >= 0.0 && x[2] <= 1.0;
}

template <class Crosses>
std::size_t brute_force(const PointCloud& cloud, const Family& family, Crosses crosses) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (int b = family.begin(i); b < family.end(i); ++b) n += crosses(cloud.x[i], cloud.x[family.neighbor[b]]);
  return n;
}

std::size_t count(const std::vector<unsigned char>& cut) { return static_cast<std::size_t>(std::count(cut.begin(), cut.end(), 1)); }

}  // namespace

// A 6×6 lattice (ΔX = 1, δ = 1.5: the 4 nearest and 4 diagonal neighbours) and the crack x = 2.5
// from y = −1 to y = 2.3: by hand, the horizontal bonds between columns 2 and 3 at y = 0, 1, 2 and
// the diagonals crossing x = 2.5 at y = 0.5 and 1.5 (two each): 7 bonds, 14 from both ends.
TEST(Precrack, CutCountOnSmallLatticeByHand) {
  const PointCloud cloud = lattice_cloud(2, {6, 6, 1}, 1.0);
  const Family family = build_family(cloud, 1.5, VolumeCorrection::linear);
  const std::vector<Crack> cracks{Crack(2, {Vec3(2.5, -1.0, 0.0), Vec3(2.5, 2.3, 0.0)})};
  EXPECT_EQ(count(cut_bonds(cloud, family, cracks)), 14u);
  // Along a row of points (y = 2) the crack cuts nothing: a point on the crack keeps its bonds.
  EXPECT_EQ(count(cut_bonds(cloud, family, {Crack(2, {Vec3(-1.0, 2.0, 0.0), Vec3(9.0, 2.0, 0.0)})})), 0u);
  // Outside the body: nothing.
  EXPECT_EQ(count(cut_bonds(cloud, family, {Crack(2, {Vec3(7.5, -1.0, 0.0), Vec3(7.5, 9.0, 0.0)})})), 0u);
}

// A slanted crack ending inside a 20×15 lattice with δ = 3.1 ΔX: the same bonds as the
// parametric intersection of every bond with it.
TEST(Precrack, SlantedSegmentMatchesBruteForce) {
  const PointCloud cloud = lattice_cloud(2, {20, 15, 1}, 1e-3);
  const Family family = build_family(cloud, 3.1e-3, VolumeCorrection::linear);
  const Vec3 p(3.17e-3, -0.53e-3, 0.0), q(11.71e-3, 8.37e-3, 0.0);
  const std::vector<unsigned char> cut = cut_bonds(cloud, family, {Crack(2, {p, q})});
  const std::size_t expected =
      brute_force(cloud, family, [&](const Vec3& a, const Vec3& b) { return segments_cross(a, b, p, q); });
  EXPECT_GT(expected, 200u);
  EXPECT_EQ(count(cut), expected);
}

// 3D: an axis-aligned rectangle (x = 2.5, y in [−1, 2.2], z in [−1, 9]) on a 6×6×6 lattice with
// δ = 1.5 (6 nearest, 12 face diagonals): by hand, between the columns x = 2 and 3 the 3 rows
// y = 0, 1, 2 of nearest bonds (6 z each: 18), the x–z diagonals on those rows (2 per row and
// gap of z, 5 gaps: 30) and the x–y diagonals crossing at y = 0.5 and 1.5 (2 each, 6 z: 24) —
// 72 bonds, 144 from both ends; and a tilted parallelogram against the brute-force solve.
TEST(Precrack, PolygonMatchesHandCountAndBruteForce) {
  const PointCloud cube = lattice_cloud(3, {6, 6, 6}, 1.0);
  const Family near = build_family(cube, 1.5, VolumeCorrection::linear);
  const Crack rectangle(3, {Vec3(2.5, -1.0, -1.0), Vec3(2.5, 2.2, -1.0), Vec3(2.5, 2.2, 9.0), Vec3(2.5, -1.0, 9.0)});
  EXPECT_EQ(count(cut_bonds(cube, near, {rectangle})), 144u);

  const PointCloud cloud = lattice_cloud(3, {9, 8, 7}, 1e-3);
  const Family family = build_family(cloud, 2.2e-3, VolumeCorrection::linear);
  const Vec3 o(2.13e-3, -0.71e-3, 0.37e-3), e1(1.91e-3, 6.03e-3, 0.52e-3), e2(0.83e-3, -0.27e-3, 5.11e-3);
  const Crack tilted(3, {o, o + e1, o + e1 + e2, o + e2});
  const std::size_t expected = brute_force(
      cloud, family, [&](const Vec3& a, const Vec3& b) { return crosses_parallelogram(a, b, o, e1, e2); });
  EXPECT_GT(expected, 500u);
  EXPECT_EQ(count(cut_bonds(cloud, family, {tilted})), expected);
}

// A PMB plate of 10×8 points (δ = 1.5 ΔX) cut by x = 4.5 ΔX from below the plate to y = 4.3 ΔX:
// the damage of a point is the fraction of its neighbours across the crack. Column 4 (and 5):
// 2 of 5 neighbours at the edge y = 0, 3 of 8 for y = 1..3, 2 of 8 at y = 4 (the diagonal to y = 5
// crosses x = 4.5 at y = 4.5, beyond the tip), 0 above; every other column 0. Exact (equal volumes).
TEST(Precrack, PlateDamageAlongTheCrack) {
  constexpr double dx = 1e-3;
  const PointCloud cloud = lattice_cloud(2, {10, 8, 1}, dx);
  const Family family = build_family(cloud, 1.5 * dx, VolumeCorrection::linear);
  PmbForce force(cloud, family, PmbModel{1e20}, Influence(), CriticalStretch{0.01, 0.25});
  force.break_bonds(cut_bonds(cloud, family, {Crack(2, {Vec3(4.5 * dx, -dx, 0.0), Vec3(4.5 * dx, 4.3 * dx, 0.0)})}));
  const std::vector<double> damage = force.damage();
  const double column[8] = {2.0 / 5.0, 3.0 / 8.0, 3.0 / 8.0, 3.0 / 8.0, 2.0 / 8.0, 0.0, 0.0, 0.0};
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 10; ++x) {
      const double expected = (x == 4 || x == 5) ? column[y] : 0.0;
      EXPECT_DOUBLE_EQ(damage[static_cast<std::size_t>(y * 10 + x)], expected) << "point (" << x << ", " << y << ")";
    }
}

// The reader's check that a crack cuts some bond of the body, made without building it, agrees with
// the bonds cut_bonds finds on the built body, for cracks inside, crossing the edge, just outside
// (within a horizon of the points, and beyond) and along a row, in 2D and 3D.
TEST(Precrack, LatticeCheckAgreesWithBuiltBody) {
  const PointCloud plate = lattice_cloud(2, {12, 9, 1}, 1e-3);
  const Family plate_family = build_family(plate, 2.5e-3, VolumeCorrection::linear);
  const double edge = 11e-3;
  for (const auto& [p, q] : std::vector<std::pair<Vec3, Vec3>>{{Vec3(3.5e-3, 2.2e-3, 0), Vec3(6.3e-3, 7.1e-3, 0)},
                                                               {Vec3(-2e-3, 4.5e-3, 0), Vec3(1.5e-3, 4.5e-3, 0)},
                                                               {Vec3(edge + 0.5e-3, -1e-3, 0), Vec3(edge + 0.5e-3, 9e-3, 0)},
                                                               {Vec3(edge + 3e-3, -1e-3, 0), Vec3(edge + 3e-3, 9e-3, 0)},
                                                               {Vec3(-1e-3, 0.0, 0), Vec3(20e-3, 0.0, 0)},
                                                               {Vec3(-1e-3, 3e-3, 0), Vec3(20e-3, 3e-3, 0)}}) {
    const Crack crack(2, {p, q});
    EXPECT_EQ(cuts_a_lattice_bond(crack, 2, {12, 9, 1}, 1e-3, 2.5e-3), count(cut_bonds(plate, plate_family, {crack})) > 0)
        << p.transpose() << " to " << q.transpose();
  }
  const PointCloud cube = lattice_cloud(3, {6, 5, 4}, 1.0);
  const Family cube_family = build_family(cube, 2.0, VolumeCorrection::linear);
  for (double x : {2.5, -0.5, 5.5, 7.5}) {
    const Crack wall(3, {Vec3(x, -1, -1), Vec3(x, 9, -1), Vec3(x, 9, 9), Vec3(x, -1, 9)});
    EXPECT_EQ(cuts_a_lattice_bond(wall, 3, {6, 5, 4}, 1.0, 2.0), count(cut_bonds(cube, cube_family, {wall})) > 0) << x;
  }
  EXPECT_TRUE(cuts_a_lattice_bond(Crack(3, {Vec3(2.5, -1, -1), Vec3(2.5, 9, -1), Vec3(2.5, 9, 9)}), 3, {6, 5, 4}, 1.0, 2.0));
  EXPECT_FALSE(cuts_a_lattice_bond(Crack(3, {Vec3(7.5, -1, -1), Vec3(7.5, 9, -1), Vec3(7.5, 9, 9)}), 3, {6, 5, 4}, 1.0, 2.0));
}

// The same check on a lattice moved off the origin ([body] origin, rows at y = −0.25 + k mm): it
// agrees with the built body for cracks between rows, on a row and outside, and a crack along
// y = 0 (a row of the unmoved lattice, which it would not cut) cuts bonds of the moved one.
TEST(Precrack, LatticeCheckFollowsTheOrigin) {
  const Vec3 origin(0.5e-3, -0.25e-3, 0.0);
  const PointCloud plate = lattice_cloud(2, {12, 9, 1}, 1e-3, origin);
  const Family family = build_family(plate, 2.5e-3, VolumeCorrection::linear);
  const auto along = [](double y) { return Crack(2, {Vec3(-1e-3, y, 0), Vec3(20e-3, y, 0)}); };
  for (double y : {0.0, 0.25e-3, 3e-3, 2.75e-3, -0.25e-3, -0.6e-3, 8.5e-3})
    EXPECT_EQ(cuts_a_lattice_bond(along(y), 2, {12, 9, 1}, 1e-3, 2.5e-3, origin),
              count(cut_bonds(plate, family, {along(y)})) > 0) << y;
  EXPECT_TRUE(cuts_a_lattice_bond(along(0.0), 2, {12, 9, 1}, 1e-3, 2.5e-3, origin));
  EXPECT_FALSE(cuts_a_lattice_bond(along(-0.6e-3), 2, {12, 9, 1}, 1e-3, 2.5e-3, origin));
  EXPECT_FALSE(cuts_a_lattice_bond(along(8.5e-3), 2, {12, 9, 1}, 1e-3, 2.5e-3, origin));
}

// The correspondence models' pre-crack: the family without the cut bonds, in the same order.
TEST(Precrack, FamilyWithoutCutBonds) {
  const PointCloud cloud = lattice_cloud(2, {6, 6, 1}, 1.0);
  const Family family = build_family(cloud, 1.5, VolumeCorrection::linear);
  const std::vector<unsigned char> cut = cut_bonds(cloud, family, {Crack(2, {Vec3(2.5, -1.0, 0.0), Vec3(2.5, 2.3, 0.0)})});
  const Family kept = without_bonds(family, cut);
  ASSERT_EQ(kept.bonds(), family.bonds() - 14u);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (int b = kept.begin(i); b < kept.end(i); ++b)
      EXPECT_FALSE(Crack(2, {Vec3(2.5, -1.0, 0.0), Vec3(2.5, 2.3, 0.0)}).cuts(cloud.x[i], cloud.x[kept.neighbor[b]]));
}
