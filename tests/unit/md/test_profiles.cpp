// Binned profiles: a slab narrower than the bin width at the upper face is measured over its own
// width, so a uniform crystal reads one density in every bin.
#include <gtest/gtest.h>

#include "md_fixture.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/diagnostics/profiles.hpp"

using namespace shockfield;
using namespace shockfield::md;

TEST(Profiles, PartialLastBinHasItsOwnWidth) {
  // Atoms on a simple cubic grid of 1 Å in a 12 × 6 × 6 Å box: one atom per Å³. Bins of 5 Å give
  // slabs [0, 5), [5, 10) and the partial [10, 12): 180, 180 and 72 atoms, the same density in
  // each; the last slab's centre is at 11 Å. Divided by the full width the last bin would read
  // 2/5 of the others (the former behaviour).
  geometry::Box box;
  box.lo = Vec3(0, 0, 0);
  box.hi = Vec3(12, 6, 6);
  Atoms atoms;
  const double mass = 63.55;
  atoms.mass = {mass};
  atoms.type_names = {"Cu"};
  std::int64_t tag = 1;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) atoms.add(Vec3(i + 0.5, j + 0.5, k + 0.5), 0, tag++);
  Simulation sim(box, std::move(atoms), fixture::potential_from("style = \"lj/cut\"\nepsilon = 0.01\nsigma = 0.8\ncutoff = 1.2\n"),
                 0.001, 0.3);
  const Profile p = bin_profile(sim, 0, 5.0);
  ASSERT_EQ(p.bins.size(), 3u);
  const double expected = mass * units::metal::amu_per_A3_to_g_per_cc;  // one atom per Å³
  const int counts[] = {180, 180, 72};
  const double centres[] = {2.5, 7.5, 11.0};
  for (int b = 0; b < 3; ++b) {
    EXPECT_EQ(p.bins[b].count, counts[b]) << "bin " << b;
    EXPECT_NEAR(p.bins[b].density, expected, 1e-12 * expected) << "bin " << b;  // exact sums
    EXPECT_DOUBLE_EQ(p.bins[b].position, centres[b]) << "bin " << b;
  }
}
