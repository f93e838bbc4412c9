// The restricted triclinic cell of geometry/box.cpp (LAMMPS's convention: a along x, b in the xy
// plane, tilts xy xz yz): fractional coordinates, wrapping, minimum image, the bounding box of
// dumps, LAMMPS's tilt limits, and the ghost images of md/ghosts.cpp, whose cutoff is measured
// along the face normals. Brute-force references: every lattice image within a few cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <Eigen/Geometry>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/ghosts.hpp"

namespace shockfield::geometry {
namespace {

Box tilted_box() {
  Box b;
  b.lo = Vec3(-1, 0.5, 2);
  b.hi = Vec3(9, 8.5, 8);
  b.tilt = Vec3(3.5, -4.0, 2.5);  // |xy|, |xz| <= 5, |yz| <= 4
  return b;
}

TEST(TriclinicBox, FractionalCoordinatesRoundTrip) {
  const Box b = tilted_box();
  // lo + h s for s = (1, 0, 0), (0, 1, 0), (0, 0, 1) are the corners lo + a, lo + b, lo + c.
  for (int d = 0; d < 3; ++d) {
    Vec3 s = Vec3::Zero();
    s[d] = 1;
    EXPECT_LT((b.from_fractional(s) - b.lo - b.edge(d)).norm(), 1e-14);
  }
  const Vec3 x(2.3, -7.1, 11.9);
  EXPECT_LT((b.from_fractional(b.to_fractional(x)) - x).norm(), 1e-13);  // round-off of ~10 flops
  EXPECT_DOUBLE_EQ(b.volume(), b.edge(0).dot(b.edge(1).cross(b.edge(2))));
}

TEST(TriclinicBox, WrapSubtractsWholeEdgesAndKeepsTheUnwrappedPosition) {
  const Box b = tilted_box();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-40, 40);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x0(u(rng), u(rng), u(rng));
    Vec3 x = x0;
    std::array<int, 3> image{2, -1, 0};
    b.wrap(x, image);
    EXPECT_TRUE(b.contains(x));
    const Vec3 s = b.to_fractional(x);
    EXPECT_GE(s.minCoeff(), 0.0);
    EXPECT_LT(s.maxCoeff(), 1.0);
    // unwrapped position unchanged: x + image·h = x0 + (2, -1, 0)·h (1e-12: tens of Å, round-off)
    EXPECT_LT((x + b.lattice_shift(image) - x0 - b.lattice_shift({2, -1, 0})).norm(), 1e-12);
  }
}

TEST(TriclinicBox, APointARoundOffBelowATiltedFaceIsPutOnIt) {
  // Found by examples/md_triclinic_shear: x = -2.4e-19 Å at y = 5.3e-20 Å with xy > 0 has s_x
  // ~ -1e-20; adding the edge rounds to s_x = 1, subtracting it gives s_x = -2.4e-23 again.
  Box b;
  b.hi = Vec3(21.69, 21.69, 21.69);
  b.tilt = Vec3(0.2169, 0, 0);
  Vec3 x(-2.3756505735724845e-19, 5.320193080506008e-20, 3.615);
  std::array<int, 3> image{0, 0, 0};
  ASSERT_TRUE(b.try_wrap(x, image));
  EXPECT_GE(b.to_fractional(x).x(), 0.0);
  EXPECT_LT(std::abs(x.x()), 1e-15);
}

TEST(TriclinicBox, MinimumImageIsLammpsReduction) {
  // LAMMPS's Domain::minimum_image brings each fractional component of a separation within one
  // half, c then b then a: check against that definition and that it is a lattice image.
  const Box b = tilted_box();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-30, 30);
  for (int k = 0; k < 200; ++k) {
    const Vec3 d(u(rng), u(rng), u(rng));
    const Vec3 m = b.minimum_image(d);
    const Vec3 s = b.fractional_vector(m);
    EXPECT_LE(s.cwiseAbs().maxCoeff(), 0.5 + 1e-12);
    const Vec3 n = b.fractional_vector(d - m);
    EXPECT_LT((n - n.array().round().matrix()).norm(), 1e-9);
  }
}

TEST(TriclinicBox, BoundingBoxRoundTripsAsLammpsWritesIt) {
  const Box b = tilted_box();
  // LAMMPS: xlo_bound = xlo + min(0, xy, xz, xy + xz), xhi_bound = xhi + max(...), y with yz.
  EXPECT_DOUBLE_EQ(b.bound_lo().x(), -1 - 4.0);
  EXPECT_DOUBLE_EQ(b.bound_hi().x(), 9 + 3.5);
  EXPECT_DOUBLE_EQ(b.bound_lo().y(), 0.5);
  EXPECT_DOUBLE_EQ(b.bound_hi().y(), 8.5 + 2.5);
  const Box c = box_from_bounds(b.bound_lo(), b.bound_hi(), b.tilt, b.boundary);
  EXPECT_LT((c.lo - b.lo).norm() + (c.hi - b.hi).norm(), 1e-14);
  EXPECT_EQ(c.tilt, b.tilt);
}

TEST(TriclinicBox, TiltsBeyondLammpsLimitsAreRefused) {
  Box b = tilted_box();
  EXPECT_NO_THROW(b.check_tilt("test"));
  b.tilt.x() = 5.01;  // > lx / 2
  try {
    b.check_tilt("cell.data");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell.data: tilt xy = 5.01"), std::string::npos) << e.what();
  }
  b = tilted_box();
  b.tilt.z() = -4.5;  // > ly / 2
  EXPECT_THROW(b.check_tilt("t"), InputError);
  b = tilted_box();
  b.boundary[2] = Boundary::fixed;  // xz, yz tilt along a non-periodic z
  EXPECT_THROW(b.check_tilt("t"), InputError);
}

TEST(TriclinicBox, GhostsHoldEveryImageWithinTheCutoff) {
  // Every periodic image within `cutoff` (true distance) of the cell must be a ghost; a thin cell
  // (face distance along z below the cutoff) needs several layers.
  Box b = tilted_box();
  b.hi.z() = 5;  // lz = 3
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  md::Atoms atoms;
  for (int i = 0; i < 30; ++i) atoms.add(b.from_fractional(Vec3(u(rng), u(rng), u(rng))), 0, i + 1);
  atoms.mass = {1.0};
  const double cutoff = 4.0;
  md::rebuild_ghosts(atoms, b, cutoff);
  const Vec3 faces = b.face_distances();
  std::size_t expected = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    for (int nx = -3; nx <= 3; ++nx)
      for (int ny = -3; ny <= 3; ++ny)
        for (int nz = -4; nz <= 4; ++nz) {
          if (nx == 0 && ny == 0 && nz == 0) continue;
          const Vec3 s = b.to_fractional(atoms.x[i] + b.lattice_shift({nx, ny, nz}));
          // within the cutoff of the cell along every face normal
          bool inside = true;
          for (int d = 0; d < 3; ++d)
            inside = inside && s[d] >= -cutoff / faces[d] && s[d] < 1 + cutoff / faces[d];
          expected += inside ? 1 : 0;
        }
  EXPECT_EQ(atoms.nghost(), expected);
  // each ghost sits at its owner's position plus its image's lattice shift
  for (std::size_t g = 0; g < atoms.nghost(); ++g)
    EXPECT_LT((atoms.x[atoms.nlocal + g] - atoms.x[atoms.ghost_owner[g]] - b.lattice_shift(atoms.ghost_image[g])).norm(),
              1e-12);
}

}  // namespace
}  // namespace shockfield::geometry
