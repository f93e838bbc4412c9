// Point clouds, families, partial volumes, influence functions and their bad input.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <filesystem>
#include <fstream>

#include "shockfield/core/error.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/influence.hpp"
#include "shockfield/pd/point_cloud.hpp"

using namespace shockfield;
using namespace shockfield::pd;

TEST(PointCloud, LatticeCountsVolumesAndOrder) {
  const PointCloud c = lattice_cloud(2, {4, 3, 1}, 0.5, Vec3(1.0, 0.0, 0.0));
  ASSERT_EQ(c.size(), 12u);
  EXPECT_DOUBLE_EQ(c.volume[5], 0.25);
  EXPECT_EQ(c.x[5], Vec3(1.5, 0.5, 0.0));  // x fastest
  EXPECT_THROW(lattice_cloud(1, {4, 2, 1}, 0.5), InputError);
  EXPECT_THROW(lattice_cloud(4, {4, 1, 1}, 0.5), InputError);
}

TEST(PointCloud, ReadsFileAndNamesTheBadLine) {
  const auto dir = shockfield::testing::scratch_path("shockfield_pd_cloud");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "good.txt") << "# x y z V\n0 0 0 1e-3\n\n1e-3 0 0 1e-3\n";
  const PointCloud c = read_cloud(dir / "good.txt", 1, 1e-3);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c.x[1][0], 1e-3);
  std::ofstream(dir / "bad.txt") << "0 0 0 1e-3\n1e-3 0 0\n";
  try {
    read_cloud(dir / "bad.txt", 1, 1e-3);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.txt:2"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "flat.txt") << "0 0 1 1e-3\n";
  EXPECT_THROW(read_cloud(dir / "flat.txt", 2, 1e-3), InputError);
}

// 1D, δ = 3ΔX: an interior point has 6 neighbours; those at 3ΔX count half (β = ½, the LAMMPS
// linear rule), nearer ones fully; a point at the end has 3.
TEST(Family, OneDimensionalHorizonAndPartialVolume) {
  const PointCloud c = lattice_cloud(1, {20, 1, 1}, 1e-5);
  const Family f = build_family(c, 3e-5, VolumeCorrection::linear);
  EXPECT_EQ(f.end(10) - f.begin(10), 6);
  EXPECT_EQ(f.end(0) - f.begin(0), 3);
  for (int b = f.begin(10); b < f.end(10); ++b) {
    const double expected = std::abs(f.length[b] - 3e-5) < 1e-12 ? 0.5 : 1.0;
    EXPECT_NEAR(f.volume_scale[b], expected, 1e-12) << "r0 = " << f.length[b];
  }
  const Family plain = build_family(c, 3e-5, VolumeCorrection::none);
  for (double beta : plain.volume_scale) EXPECT_EQ(beta, 1.0);
}

// 3D, δ = 3.0002ΔX: the 122 lattice points within 3ΔX of an interior point (LAMMPS counts the same).
TEST(Family, ThreeDimensionalNeighbourCountAndSymmetry) {
  const PointCloud c = lattice_cloud(3, {9, 9, 9}, 1.0);
  const Family f = build_family(c, 3.0002, VolumeCorrection::linear);
  const std::size_t centre = 4 + 9 * (4 + 9 * 4);
  EXPECT_EQ(f.end(centre) - f.begin(centre), 122);
  // Every bond is stored from both ends with the same length and factor.
  for (std::size_t i = 0; i < c.size(); ++i)
    for (int b = f.begin(i); b < f.end(i); ++b) {
      const int j = f.neighbor[b];
      bool found = false;
      for (int a = f.begin(j); a < f.end(j); ++a)
        if (f.neighbor[a] == static_cast<int>(i)) found = f.length[a] == f.length[b] && f.volume_scale[a] == f.volume_scale[b];
      ASSERT_TRUE(found) << i << " -> " << j;
    }
}

TEST(Family, HorizonSmallerThanSpacingIsAnInputError) {
  const PointCloud c = lattice_cloud(1, {10, 1, 1}, 1e-5);
  try {
    build_family(c, 0.5e-5, VolumeCorrection::linear);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("smaller than the spacing"), std::string::npos) << e.what();
  }
  EXPECT_THROW(volume_correction_from_name("cubic"), InputError);
}

TEST(Influence, ValuesByName) {
  EXPECT_DOUBLE_EQ(Influence::from_name("constant")(2.0, 3.0), 1.0);
  EXPECT_DOUBLE_EQ(Influence::from_name("inverse")(2.0, 3.0), 0.5);
  EXPECT_DOUBLE_EQ(Influence::from_name("conical")(2.0, 3.0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(Influence::from_name("gaussian")(3.0, 3.0), std::exp(-1.0));
  try {
    Influence::from_name("cubic");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gaussian"), std::string::npos) << e.what();
  }
}

// Neighbours at exactly δ = m·ΔX are found whatever the lattice length (the cell list's cells
// must be wider than the cut-off, not equal to it).
TEST(Family, NeighboursOnTheHorizonAreNeverMissed) {
  for (int n : {1200, 1600, 1601}) {
    const PointCloud c = lattice_cloud(1, {n, 1, 1}, 1e-5);
    const Family f = build_family(c, 3e-5, VolumeCorrection::linear);
    for (int i = 3; i < n - 3; ++i) ASSERT_EQ(f.end(i) - f.begin(i), 6) << "point " << i << " of " << n;
  }
}
