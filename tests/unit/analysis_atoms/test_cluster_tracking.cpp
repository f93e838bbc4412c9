// Cluster tracking and growth laws (analysis/atoms/cluster_tracking): lattice-site spheres whose
// radius grows as R = R0 t^0.5 must give a, b, c, L ~ t^0.5, A ~ t^1, V ~ t^1.5 (the laws Xu et
// al. (2015) Fig 72 report for hcp domains). Tolerances: the spheres are sets of lattice sites
// (60 to 1,700 atoms), whose moments differ from the continuum ones by a few per cent at the
// smallest radius; measured 0.4992 (a, b, c, L), 0.998 (A), 1.498 (V), 1.493 (atomic volume), so
// the bounds are 0.01 on linear sizes and 0.02 on A and V — twice the measured discreteness. Tracking keeps each domain's number when the largest-first order of
// the clusters swaps, and a domain nucleated later gets a new track.
#include <gtest/gtest.h>

#include <cmath>

#include "lattice_frames.hpp"
#include "shockfield/analysis/atoms/cluster_tracking.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

struct Domain {
  Vec3 centre;
  double r0;        // Å at t = 1
  long long birth;  // timestep of nucleation
  double power;
};

ClusterResult clusters_at(const AtomFrame& frame, const std::vector<Domain>& domains, long long step) {
  std::vector<bool> selected(frame.size(), false);
  for (const Domain& d : domains) {
    if (step <= d.birth) continue;
    const double r = d.r0 * std::pow(double(step - d.birth), d.power);
    for (std::size_t i = 0; i < frame.size(); ++i)
      if (frame.box.minimum_image(frame.positions[i] - d.centre).norm() <= r) selected[i] = true;
  }
  const DefectClusters clusters{3.0, 1};
  const NeighborTable table(frame, clusters.request());
  return clusters.compute(frame, table, selected);
}

TEST(ClusterTracking, SphereGrowingAsSqrtTime) {
  const AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 14);  // 50.6 Å box
  const std::vector<Domain> one{{Vec3::Constant(25.3), 0.5, 0, 0.5}};
  ClusterTracker tracker;
  for (long long step = 100; step <= 1000; step += 100)
    tracker.add(static_cast<std::size_t>(step / 100), step, frame.ids, clusters_at(frame, one, step));
  ASSERT_EQ(tracker.tracks().size(), 1u);
  const auto fits = fit_growth(tracker.tracks()[0], 0, 0.001);
  ASSERT_EQ(fits.size(), 7u);
  const double expected[7] = {0.5, 0.5, 0.5, 0.5, 1.0, 1.5, 1.5}, tolerance[7] = {0.01, 0.01, 0.01, 0.01, 0.02, 0.02, 0.02};
  for (int q = 0; q < 7; ++q) {
    EXPECT_NEAR(fits[q].exponent, expected[q], tolerance[q]) << fits[q].quantity;
    EXPECT_EQ(fits[q].points, 10);
    EXPECT_GT(fits[q].exponent_stderr, 0) << fits[q].quantity;
  }
  // Prefactor of a: a = C t^k with t in ps (dt = 0.001 ps per step), a ≈ R = 0.5 (t/0.001)^0.5.
  EXPECT_NEAR(fits[0].prefactor * std::pow(1.0, fits[0].exponent), 0.5 * std::pow(1000.0, 0.5), 0.1 * 15.8);
}

TEST(ClusterTracking, TracksKeepTheirNumbers) {
  const AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, 3.615, 14);
  // Domain 1 from step 0, slow; domain 2 nucleates at step 300 far away and grows faster, so it
  // becomes the largest cluster (index 0) by the end.
  const std::vector<Domain> two{{Vec3(12, 12, 12), 1.2, 0, 0.3}, {Vec3(38, 38, 38), 0.6, 300, 0.55}};
  ClusterTracker tracker;
  std::vector<std::size_t> first_cluster_track;
  for (long long step = 100; step <= 1000; step += 100) {
    tracker.add(static_cast<std::size_t>(step / 100), step, frame.ids, clusters_at(frame, two, step));
    first_cluster_track.push_back(static_cast<std::size_t>(tracker.last_tracks().front()));
  }
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_EQ(tracker.tracks()[0].points.size(), 10u);
  EXPECT_EQ(tracker.tracks()[1].points.size(), 7u);  // steps 400..1000
  EXPECT_EQ(tracker.tracks()[1].points.front().timestep, 400);
  EXPECT_EQ(first_cluster_track.front(), 1u);
  EXPECT_EQ(first_cluster_track.back(), 2u);  // the largest cluster is domain 2 at the end
  for (const TrackPoint& p : tracker.tracks()[0].points) EXPECT_LT((p.shape.centre - Vec3(12, 12, 12)).norm(), 1.0);
  const auto fits = fit_growth(tracker.tracks()[1], 300, 1.0);
  EXPECT_NEAR(fits[3].exponent, 0.55, 0.04);  // L of domain 2, from its nucleation step
}

TEST(ClusterTracking, PowerLawNeedsThreePoints) {
  EXPECT_THROW(fit_power_law("V", {1, 2, 0}, {1, 2, 3}), InputError);
  const auto fit = fit_power_law("V", {1, 2, 4, 8}, {3, 3 * std::pow(2, 1.5), 3 * 8.0, 3 * std::pow(8, 1.5)});
  EXPECT_NEAR(fit.exponent, 1.5, 1e-12);
  EXPECT_NEAR(fit.prefactor, 3.0, 1e-12);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
