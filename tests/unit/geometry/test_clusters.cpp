// Clusters from the Delaunay division: single linkage equals brute-force single linkage over all
// pairs (union-find, O(n²)) in 2D and 3D; the paper's rule (simplices with shortest edge <= d,
// face-connected) on an example where it differs from single linkage. Exact: labels must match.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/delaunay_clusters.hpp"

namespace shockfield::geometry {
namespace {

/// Brute-force single linkage: every pair closer than d joined; labels by lowest point.
template <int N>
std::vector<std::int32_t> brute_force(const std::vector<std::array<double, N>>& p, double d) {
  std::vector<std::int32_t> parent(p.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      double s = 0;
      for (int k = 0; k < N; ++k) s += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
      if (std::sqrt(s) < d) {
        const auto a = find(i), b = find(j);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
  std::vector<std::int32_t> label(p.size()), number(p.size(), -1);
  std::int32_t count = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto r = find(i);
    if (number[r] < 0) number[r] = count++;
    label[i] = number[r];
  }
  return label;
}

template <int N>
std::vector<std::array<double, N>> blobs(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 10);
  std::normal_distribution<double> g;
  std::vector<std::array<double, N>> centres(25), pts(n);
  for (auto& c : centres)
    for (double& x : c) x = u(rng);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < N; ++k) pts[i][k] = centres[i % 25][k] + 0.3 * g(rng);
  return pts;
}

template <int N>
void check_single_linkage(std::uint64_t seed) {
  auto pts = blobs<N>(1500, seed);
  for (int i = 0; i < 20; ++i) pts.push_back(pts[7 * i]);  // duplicates join their original
  const auto d = delaunay_division<N>(pts);
  for (double cut : {0.05, 0.2, 0.5, 1.0}) {
    const auto c = single_linkage_clusters<N>(d, cut);
    EXPECT_EQ(c.label, brute_force<N>(pts, cut)) << "d = " << cut;
    EXPECT_EQ(std::accumulate(c.size.begin(), c.size.end(), std::size_t{0}), pts.size());
  }
}

TEST(DelaunayClusters, SingleLinkageEqualsBruteForce) {
  check_single_linkage<2>(1);
  check_single_linkage<3>(2);
}

// Two tight pairs 5 apart: every triangle of the division has a short edge (0.1), so the paper's
// rule keeps them all and finds one cluster; single linkage with d = 1 finds the two pairs.
TEST(DelaunayClusters, SeedRuleDiffersFromSingleLinkage) {
  const std::vector<std::array<double, 2>> pts{{0, 0}, {0.1, 0}, {5, 0.05}, {5.1, 0.05}};
  const auto d = delaunay_division<2>(pts);
  ASSERT_EQ(d.simplices.size(), 2u);
  const auto seed = seed_rule_clusters<2>(d, 1.0);
  EXPECT_EQ(seed.count, 1u);
  EXPECT_EQ(seed.label, (std::vector<std::int32_t>{0, 0, 0, 0}));
  const auto single = single_linkage_clusters<2>(d, 1.0);
  EXPECT_EQ(single.count, 2u);
  EXPECT_EQ(single.label, (std::vector<std::int32_t>{0, 0, 1, 1}));
  // With d below every edge, the paper's rule removes every triangle: four single points.
  EXPECT_EQ(seed_rule_clusters<2>(d, 0.05).count, 4u);
}

// Well-separated blobs (gaps of 19 against d = 0.6, spacing within a blob far below d): single
// linkage finds the four; the paper's rule as written joins them all, because every simplex
// bridging two blobs has at least two vertices in one blob, hence a short edge, and is kept.
TEST(DelaunayClusters, SeedRuleJoinsSeparatedBlobs) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<std::array<double, 3>> pts;
  for (int b = 0; b < 4; ++b)
    for (int i = 0; i < 300; ++i) pts.push_back({20.0 * b + u(rng), u(rng), u(rng)});
  const auto d = delaunay_division<3>(pts);
  const auto seed = seed_rule_clusters<3>(d, 0.6);
  const auto single = single_linkage_clusters<3>(d, 0.6);
  EXPECT_EQ(single.count, 4u);
  EXPECT_EQ(seed.count, 1u);
  EXPECT_THROW(seed_rule_clusters<3>(d, -1.0), InputError);
  EXPECT_THROW(single_linkage_clusters<3>(d, std::nan("")), InputError);
}

}  // namespace
}  // namespace shockfield::geometry
