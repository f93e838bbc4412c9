// The bond count of a PD lattice body counted before it is built (pd/lattice_bonds.hpp) is the
// number of bonds build_family finds, exactly, in 1D, 2D and 3D, for horizons on and off whole
// spacings and bodies thinner than the horizon; and the case reader refuses a horizon whose bond
// list exceeds kMaxBonds by key, with the count, before anything is built (issue 14).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/pd/case_file.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/lattice_bonds.hpp"
#include "shockfield/pd/point_cloud.hpp"

using namespace shockfield;
using namespace shockfield::pd;

TEST(LatticeBonds, EqualsTheBuiltFamilyExactly) {
  struct Body {
    int dim;
    std::array<int, 3> counts;
    double m;
  };
  const double dx = 1e-5;
  for (const Body& b : {Body{1, {40, 1, 1}, 3.0}, Body{1, {5, 1, 1}, 9.7}, Body{2, {17, 11, 1}, 3.015},
                        Body{2, {30, 4, 1}, 2.5}, Body{3, {9, 7, 12}, 3.0}, Body{3, {10, 3, 8}, 2.2},
                        Body{3, {6, 6, 6}, 1.0}, Body{3, {4, 5, 6}, 40.0}}) {
    const PointCloud cloud = lattice_cloud(b.dim, b.counts, dx);
    const Family family = build_family(cloud, b.m * dx, VolumeCorrection::linear);
    EXPECT_EQ(lattice_bonds(b.dim, b.counts, b.m), static_cast<double>(family.bonds()))
        << b.dim << "D " << b.counts[0] << " x " << b.counts[1] << " x " << b.counts[2] << ", m = " << b.m;
  }
}

// Far from the surfaces a 3D point has the lattice points of the ball of radius m: for a body much
// larger than the horizon the count per point approaches 4/3·π·m³ (within the lattice-count
// error and the surface share, 15% at m = 10 on a 200³ body).
TEST(LatticeBonds, GrowsAsTheHorizonCubed) {
  const double points = 200.0 * 200.0 * 200.0;
  const double per_point = lattice_bonds(3, {200, 200, 200}, 10.0) / points;
  EXPECT_NEAR(per_point, 4.0 / 3.0 * std::numbers::pi * 1000.0, 0.15 * 4189.0);
  EXPECT_GT(lattice_bonds(3, {200, 200, 200}, 20.0) / lattice_bonds(3, {200, 200, 200}, 10.0), 7.0);
}

TEST(LatticeBonds, TooManyBondsAreRefusedByKeyBeforeBuilding) {
  // 10^6 points (within the 10^8 point bound) at m = 10: 3.72·10^9 bonds (~150 GB).
  const Config root = Config::parse(R"(method = "pd"
[body]
dim = 3
counts = [100, 100, 100]
spacing = 1e-5
horizon_factor = 10.0
[material]
model = "pmb"
density = 8000.0
micromodulus = 1e20
critical_stretch = 0.01
[solver]
end_time = 1e-7
)", "big.toml");
  try {
    read_pd_case(root);
    ADD_FAILURE() << "a 3.7e9-bond body was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* part : {"big.toml", "body.horizon_factor", "1e+06 points", "bonds", "at most 2e+09 bonds"})
      EXPECT_NE(what.find(part), std::string::npos) << part << " not in: " << what;
  }
  EXPECT_GT(lattice_bonds(3, {100, 100, 100}, 10.0), kMaxBonds);
  EXPECT_LT(lattice_bonds(3, {100, 100, 100}, 7.0), kMaxBonds);  // m = 7: accepted
}
