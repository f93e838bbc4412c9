// Clusters of selected atoms and their central-moment ellipsoids, on lattice-point ellipsoids
// whose moments are known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/defect_clusters.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/core/error.hpp"
#include "unit/analysis_atoms/lattice_frames.hpp"

namespace shockfield::analysis::atoms {
namespace {

const double kA0 = 3.615;
const double kBond = 0.8536 * kA0;  // between the fcc first and second shells

// Selects the sites inside the ellipsoid (semi-axes s along x, y, z) centred at c, with the
// periodic minimum image; returns the selected sites' separations from c.
std::vector<Vec3> select_ellipsoid(const AtomFrame& f, const Vec3& c, const Vec3& s, std::vector<bool>& selected) {
  std::vector<Vec3> inside;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec3 d = f.box.minimum_image(f.positions[i] - c);
    if (d.cwiseQuotient(s).squaredNorm() <= 1.0) {
      selected[i] = true;
      inside.push_back(d);
    }
  }
  return inside;
}

TEST(DefectClusters, EllipsoidAcrossPeriodicCorner) {
  const AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, kA0, 12);
  std::vector<bool> selected(frame.size(), false);
  const Vec3 s(16.0, 10.0, 7.0);
  // Centred at the box corner: the ellipsoid is cut into 8 pieces by the periodic faces.
  const auto inside = select_ellipsoid(frame, frame.box.lo + Vec3(0.3, 0.2, 0.1), s, selected);
  const DefectClusters clusters{kBond, 1};
  const NeighborTable table(frame, clusters.request());
  const auto r = clusters.compute(frame, table, selected);
  ASSERT_EQ(r.clusters.size(), 1u);
  const Cluster& c = r.clusters[0];
  ASSERT_EQ(c.size, inside.size());
  // The exact central moments of the selected sites (unwrapped by hand): round-off only.
  Vec3 mean = Vec3::Zero();
  for (const Vec3& d : inside) mean += d;
  mean /= static_cast<double>(inside.size());
  Mat3 m = Mat3::Zero();
  for (const Vec3& d : inside) m += (d - mean) * (d - mean).transpose();
  m /= static_cast<double>(inside.size());
  EXPECT_LT((c.moment - m).norm(), 1e-9 * m.norm());
  // Semi-axes √(5λ) against the continuum ellipsoid: lattice discreteness, a few % at ~400 sites.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c.semi_axes[k], s[k], 0.06 * s[k]) << k;
  // The longest axis along x, the shortest along z: the off-site centre makes the site set
  // slightly asymmetric (axes tilted by < 1°, |cos| > 0.9998); each axis is an eigenvector of M.
  EXPECT_GT(std::abs(c.axes.col(0).x()), 0.9998);
  EXPECT_GT(std::abs(c.axes.col(2).z()), 0.9998);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((m * c.axes.col(k) - c.semi_axes[k] * c.semi_axes[k] / 5.0 * c.axes.col(k)).norm(), 1e-9 * m.norm());
  const double volume = 4.0 / 3.0 * std::numbers::pi * s.prod();
  EXPECT_NEAR(c.atomic_volume, volume, 0.10 * volume);
  EXPECT_NEAR(c.ellipsoid_volume, volume, 0.15 * volume);
  EXPECT_TRUE(frame.box.contains(c.centre));
}

TEST(DefectClusters, SeparateBlobsLargestFirstAndMinimumSize) {
  const AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, kA0, 10);
  std::vector<bool> selected(frame.size(), false);
  const Vec3 mid = frame.box.lo + 0.5 * frame.box.length();
  const auto small = select_ellipsoid(frame, mid - Vec3(9, 0, 0), Vec3(4, 4, 4), selected);
  const auto large = select_ellipsoid(frame, mid + Vec3(8, 0, 0), Vec3(6, 6, 6), selected);
  std::size_t lone = 0;  // one isolated selected atom far from both
  while ((frame.positions[lone] - mid).norm() < 15.0) ++lone;
  selected[lone] = true;
  const DefectClusters all{kBond, 1};
  const NeighborTable table(frame, all.request());
  const auto r = all.compute(frame, table, selected);
  ASSERT_EQ(r.clusters.size(), 3u);
  EXPECT_EQ(r.clusters[0].size, large.size());
  EXPECT_EQ(r.clusters[1].size, small.size());
  EXPECT_EQ(r.clusters[2].size, 1u);
  const auto dropped = DefectClusters{kBond, 2}.compute(frame, table, selected);
  EXPECT_EQ(dropped.clusters.size(), 2u);
  EXPECT_EQ(dropped.cluster_of[lone], -1);
}

// Clusters selected by excess energy through analyze_structure: the excess source runs after the
// structure analyses (it sees their results, as --excess-energy auto needs the fcc atoms) and
// before the clusters, which select atoms above a threshold. Two balls of high-energy atoms.
TEST(DefectClusters, SelectedByExcessEnergyInAnalyzeStructure) {
  const AtomFrame frame = testing::crystal(md::LatticeStyle::fcc, kA0, 10);
  std::vector<bool> ball(frame.size(), false);
  const Vec3 mid = frame.box.lo + 0.5 * frame.box.length();
  const auto small = select_ellipsoid(frame, mid - Vec3(9, 0, 0), Vec3(4, 4, 4), ball);
  const auto large = select_ellipsoid(frame, mid + Vec3(8, 0, 0), Vec3(6, 6, 6), ball);
  StructureAnalyses analyses;
  analyses.adaptive_cna = AdaptiveCna{};
  std::size_t fcc_seen = 0;
  analyses.excess_energy = [&](const StructureAnalysisResult& r) {
    fcc_seen = r.adaptive_cna->counts.of(Structure::fcc);
    std::vector<double> e(frame.size(), 0.05);  // thermal-sized excess: below the threshold
    for (std::size_t i = 0; i < e.size(); ++i)
      if (ball[i]) e[i] = 0.1 + 1e-9;  // just above it
    return ExcessEnergy{e, -3.54};
  };
  analyses.clusters = DefectClusters{kBond, 1};
  analyses.select = [](const StructureAnalysisResult& r) {
    std::vector<bool> out(r.excess_energy.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = r.excess_energy[i] > 0.1;
    return out;
  };
  const auto r = analyze_structure(frame, analyses);
  EXPECT_EQ(fcc_seen, frame.size());  // the source saw the a-CNA result
  ASSERT_EQ(r.excess_energy.size(), frame.size());
  EXPECT_EQ(r.excess_reference, -3.54);  // the source's reference is kept for structures.csv
  ASSERT_EQ(r.clusters->clusters.size(), 2u);
  EXPECT_EQ(r.clusters->clusters[0].size, large.size());
  EXPECT_EQ(r.clusters->clusters[1].size, small.size());
  // A source of the wrong length is refused.
  analyses.excess_energy = [](const StructureAnalysisResult&) { return ExcessEnergy{std::vector<double>(3, 0.0), 0.0}; };
  EXPECT_THROW(analyze_structure(frame, analyses), InputError);
}

}  // namespace
}  // namespace shockfield::analysis::atoms
