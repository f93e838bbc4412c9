// The packed bond measurement (pd/bond_stretch.hpp: SSE2 sqrt and divisions two bonds at a time,
// a scalar tail) gives bit for bit what the per-bond scalar code gives: r = Eigen's norm() of
// y_j − y_i, e = r − r0 zeroed below LAMMPS's NEAR_ZERO, s = e/r0, and the pull t/r with 0 at r = 0.
// Bitwise (EXPECT_EQ on doubles) because the LAMMPS parity tests need damage identical: one
// rounding of s can flip a bond at the critical stretch. Odd and even family sizes exercise the
// tail; displacements of 1e-17 m put extensions on both sides of NEAR_ZERO; one neighbour sits on
// point i (r = 0).
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/rng.hpp"
#include "shockfield/pd/bond_stretch.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/point_cloud.hpp"

using namespace shockfield;
using namespace shockfield::pd;

TEST(BondStretches, PackedEqualsScalarBitForBit) {
  for (const int edge : {4, 5}) {
    const double dx = 1e-3;
    const PointCloud cloud = lattice_cloud(3, {edge, edge, edge}, dx);
    const Family family = build_family(cloud, 2.01 * dx, VolumeCorrection::linear);
    std::vector<Vec3> y = cloud.x;
    for (std::size_t i = 0; i < y.size(); ++i)
      for (int d = 0; d < 3; ++d) {
        const double u = 2.0 * rng::uniform(77, i, d) - 1.0;
        y[i][d] += i % 3 == 0 ? 1e-17 * u : 1e-5 * u;  // a third of the points barely displaced
      }
    y[1] = y[0];  // r = 0 for the bond 0 → 1
    BondStretches bonds;
    std::size_t near_zero = 0, odd = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      bonds.measure(family, i, y);
      const int b0 = family.begin(i), m = family.end(i) - b0;
      odd += m % 2;
      for (int k = 0; k < m; ++k) bonds.pull[k] = 3.0 * k + 1.0;
      bonds.divide_pull_by_length(static_cast<std::size_t>(m));
      for (int k = 0; k < m; ++k) {
        const int b = b0 + k;
        const Vec3 bond = y[family.neighbor[b]] - y[i];
        const double r = bond.norm();
        double e = r - family.length[b];
        if (std::abs(e) < kNearZeroExtension) e = 0.0, ++near_zero;
        EXPECT_EQ(bonds.dx[k], bond[0]);
        EXPECT_EQ(bonds.r[k], r) << "point " << i << " bond " << k;
        EXPECT_EQ(bonds.extension[k], e) << "point " << i << " bond " << k;
        EXPECT_EQ(bonds.stretch[k], e / family.length[b]) << "point " << i << " bond " << k;
        EXPECT_EQ(bonds.pull[k], r > 0.0 ? (3.0 * k + 1.0) / r : 0.0) << "point " << i << " bond " << k;
      }
    }
    EXPECT_GT(near_zero, 0u) << "no extension below NEAR_ZERO: the zeroing is not exercised";
    EXPECT_GT(odd, 0u) << "no odd family: the scalar tail is not exercised";
  }
}
