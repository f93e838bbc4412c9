// Periodic wrapping by floor (geometry/box.cpp), in constant time: the loop it replaced never
// ended for a coordinate of 1e300 or 9.2e18, or a box 1e-300 long (issue 14). Ghost images of a
// box far thinner than the interaction range are refused instead of copying atoms without end.
#include <gtest/gtest.h>

#include <chrono>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/ghosts.hpp"

namespace shockfield::geometry {
namespace {

Box unit_box() {
  Box b;
  b.lo = Vec3(-1, 0, 2);
  b.hi = Vec3(1, 3, 7);
  return b;
}

TEST(BoxWrap, AgreesWithStepByStepWrappingNearTheBox) {
  // The old loop added or removed one length at a time: the same position and image, exactly,
  // for positions a few lengths out (tolerance 0: both subtract whole lengths; these are exact).
  const Box b = unit_box();
  for (double x : {-5.0, -3.0, -1.0, -0.5, 0.0, 1.0, 2.5, 9.0}) {
    Vec3 p(x, 3.0 * x, x + 4.0);
    std::array<int, 3> image{1, -2, 0};
    Vec3 q = p;
    std::array<int, 3> expected = image;
    for (int d = 0; d < 3; ++d) {
      const double l = b.hi[d] - b.lo[d];
      while (q[d] < b.lo[d]) q[d] += l, --expected[d];
      while (q[d] >= b.hi[d]) q[d] -= l, ++expected[d];
    }
    b.wrap(p, image);
    EXPECT_EQ(p, q) << x;
    EXPECT_EQ(image, expected) << x;
    EXPECT_TRUE(b.contains(p));
  }
}

TEST(BoxWrap, FarPositionsWrapOrFailAtOnce) {
  const Box b = unit_box();
  const auto start = std::chrono::steady_clock::now();
  Vec3 p(2e9 + 0.5, 1, 3);
  std::array<int, 3> image{0, 0, 0};
  ASSERT_TRUE(b.try_wrap(p, image));
  EXPECT_DOUBLE_EQ(p.x(), 0.5);
  EXPECT_EQ(image[0], 1000000000);
  for (double far : {1e300, 9.2e18, -1e20, std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN()}) {
    Vec3 q(far, 1, 3);
    std::array<int, 3> im{0, 0, 0};
    EXPECT_FALSE(b.try_wrap(q, im)) << far;
    EXPECT_EQ(im, (std::array<int, 3>{0, 0, 0}));
    EXPECT_THROW(b.wrap(q, im), RunError);
  }
  Box thin = unit_box();
  thin.hi.x() = thin.lo.x() + 1e-300;
  Vec3 q(0.5, 1, 3);
  std::array<int, 3> im{0, 0, 0};
  EXPECT_FALSE(thin.try_wrap(q, im));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
}

TEST(BoxWrap, GhostsOfADegenerateBoxAreRefused) {
  Box thin = unit_box();
  thin.hi.x() = thin.lo.x() + 1e-300;
  md::Atoms atoms;
  atoms.mass = {1.0};
  atoms.add(Vec3(thin.lo.x(), 1, 3), 0, 1);
  EXPECT_THROW(md::rebuild_ghosts(atoms, thin, 6.0), RunError);
}

}  // namespace
}  // namespace shockfield::geometry
