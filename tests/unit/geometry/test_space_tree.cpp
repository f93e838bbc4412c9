// The SHT against brute force: nearest (MS2), k-nearest and radius queries on 10^5 points
// (uniform, Gaussian blobs, on a sphere), on spheres whose radii spread over four decades (a
// custom minimum search: distance to the sphere), in 1D, 2D and 3D; and random insert/remove
// sequences with the invariant checker after every operation. Tolerance: none — the tree computes
// the same doubles as the brute force, so results must be identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "shockfield/geometry/space_tree.hpp"
#include "shockfield/geometry/space_tree_queries.hpp"

namespace shockfield::geometry {
namespace {

template <int N>
using Points = std::vector<std::array<double, N>>;

template <int N>
auto adaptor_of(const Points<N>& pts) {
  return points_adaptor<N>(pts.size(), [&pts](std::size_t i, int k) { return pts[i][k]; });
}

template <int N>
double dist2(const std::array<double, N>& a, const std::array<double, N>& b) {
  double s = 0;
  for (int k = 0; k < N; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

enum class Cloud { Uniform, Blobs, Sphere };

template <int N>
Points<N> make_cloud(Cloud kind, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  Points<N> pts(n);
  Points<N> centres(20);
  for (auto& c : centres)
    for (double& x : c) x = u(rng);
  for (std::size_t i = 0; i < n; ++i) {
    auto& p = pts[i];
    if (kind == Cloud::Uniform) {
      for (double& x : p) x = u(rng);
    } else if (kind == Cloud::Blobs) {
      const auto& c = centres[i % centres.size()];
      const double w = 1e-3 * std::pow(10.0, 2.0 * (i % 3));  // blob widths 1e-3, 0.1, 10
      for (int k = 0; k < N; ++k) p[k] = c[k] + w * g(rng);
    } else {
      double r2 = 0;
      for (double& x : p) {
        x = g(rng);
        r2 += x * x;
      }
      for (double& x : p) x /= std::sqrt(r2);
    }
  }
  return pts;
}

template <int N>
void check_queries(const Points<N>& pts, std::size_t queries, std::uint64_t seed) {
  const auto adaptor = adaptor_of<N>(pts);
  const auto tree = SpaceTree<N, decltype(adaptor)>::with_all(adaptor);
  ASSERT_EQ(tree.check(), "");
  ASSERT_EQ(tree.size(), pts.size());
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
  std::normal_distribution<double> g;
  std::vector<double> d2(pts.size());
  for (std::size_t t = 0; t < queries; ++t) {
    std::array<double, N> q = pts[pick(rng)];
    for (double& x : q) x += 0.01 * g(rng);
    for (std::size_t i = 0; i < pts.size(); ++i) d2[i] = dist2<N>(q, pts[i]);
    const auto nn = nearest<N>(tree, q);
    const std::size_t best = std::min_element(d2.begin(), d2.end()) - d2.begin();
    ASSERT_EQ(nn.distance, std::sqrt(d2[best])) << "query " << t;
    const std::size_t k = 8;
    const auto knn = k_nearest<N>(tree, q, k);
    std::vector<double> sorted = d2;
    std::partial_sort(sorted.begin(), sorted.begin() + k, sorted.end());
    ASSERT_EQ(knn.size(), k);
    for (std::size_t j = 0; j < k; ++j) ASSERT_EQ(knn[j].distance, std::sqrt(sorted[j]));
    const double r = std::sqrt(sorted[k * 4]);  // a radius holding about 33 points
    auto in = within_radius<N>(tree, q, r);
    std::sort(in.begin(), in.end());
    std::vector<std::uint32_t> expected;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (d2[i] <= r * r) expected.push_back(static_cast<std::uint32_t>(i));
    ASSERT_EQ(in, expected) << "query " << t;
  }
}

TEST(SpaceTree, QueriesEqualBruteForceOnUniformBlobsAndSphere3D) {
  for (Cloud c : {Cloud::Uniform, Cloud::Blobs, Cloud::Sphere})
    check_queries<3>(make_cloud<3>(c, 100000, 3 + int(c)), 60, 5);
}

TEST(SpaceTree, QueriesEqualBruteForceIn1DAnd2D) {
  check_queries<1>(make_cloud<1>(Cloud::Blobs, 20000, 8), 100, 9);
  check_queries<2>(make_cloud<2>(Cloud::Uniform, 50000, 10), 100, 11);
  check_queries<2>(make_cloud<2>(Cloud::Sphere, 20000, 12), 100, 13);
}

// Spheres with radii from 1e-4 to 1: placed by size, found by a minimum search whose value is the
// distance to the sphere's surface (0 inside) and a radius query on their boxes.
TEST(SpaceTree, SpheresOverFourDecadesOfSize) {
  struct Spheres {
    Points<3> centre;
    std::vector<double> radius;
    std::size_t size() const { return centre.size(); }
    void bounds(std::size_t i, std::array<double, 3>& lo, std::array<double, 3>& hi) const {
      for (int k = 0; k < 3; ++k) {
        lo[k] = centre[i][k] - radius[i];
        hi[k] = centre[i][k] + radius[i];
      }
    }
  } s;
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 10.0), decade(-4.0, 0.0);
  for (int i = 0; i < 20000; ++i) {
    s.centre.push_back({u(rng), u(rng), u(rng)});
    s.radius.push_back(std::pow(10.0, decade(rng)));
  }
  const auto tree = SpaceTree<3, Spheres>::with_all(s);
  ASSERT_EQ(tree.check(), "");
  auto surface_distance = [&](std::uint32_t i, const std::array<double, 3>& q) {
    return std::max(std::sqrt(dist2<3>(q, s.centre[i])) - s.radius[i], 0.0);
  };
  for (int t = 0; t < 100; ++t) {
    const std::array<double, 3> q{u(rng), u(rng), u(rng)};
    const auto found = tree.minimum_search(
        3,
        [&](const TreeCube<3>& c) {
          return std::pair{std::sqrt(c.distance2_to(q)), std::sqrt(c.farthest2_from(q))};
        },
        [&](std::uint32_t i) { return surface_distance(i, q); });
    std::vector<double> all;
    for (std::uint32_t i = 0; i < s.size(); ++i) all.push_back(surface_distance(i, q));
    std::sort(all.begin(), all.end());
    ASSERT_EQ(found.size(), 3u);
    for (int j = 0; j < 3; ++j) ASSERT_EQ(found[j].value, all[j]) << "query " << t;
    auto in = within_radius<3>(tree, q, 0.3);
    std::sort(in.begin(), in.end());
    std::vector<std::uint32_t> expected;
    double nearest_box2 = INFINITY;
    for (std::uint32_t i = 0; i < s.size(); ++i) {
      if (box_distance2<3>(tree, i, q) <= 0.09) expected.push_back(i);
      nearest_box2 = std::min(nearest_box2, box_distance2<3>(tree, i, q));
    }
    ASSERT_EQ(in, expected);
    // MS2 on boxes: the sub-cubes have margins, so their distances take the per-sub-cube path.
    ASSERT_EQ(nearest<3>(tree, q).distance, std::sqrt(nearest_box2)) << "query " << t;
  }
}

// The distances of all sub-cubes at once (per axis, shared by the sub-cubes on one side) must
// be bitwise those of each sub-cube's own region, with and without margins, or the searches
// built on them would prune differently from the per-cube form and from brute force.
template <int N>
void check_sub_cube_distances(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_int_distribution<int> level(-6, 3);
  for (int t = 0; t < 2000; ++t) {
    TreeCube<N> cube;
    cube.half = std::ldexp(1.0, level(rng));  // dyadic, as in the tree
    for (double& c : cube.centre) c = std::round(u(rng) / cube.half) * cube.half;
    std::array<double, N> q;
    for (int k = 0; k < N; ++k) q[k] = cube.centre[k] + cube.half * u(rng);
    std::array<double, (1 << N)> margins{}, fast;
    if (t % 2 == 1)
      for (double& m : margins) m = t % 4 == 1 ? 0.0 : 0.1 * cube.half * (u(rng) + 3.0);
    if (t % 4 == 1) margins[t % (1 << N)] = 1e-3 * cube.half;  // one sub-cube with a margin
    sub_cube_distances2<N>(cube, margins, q, fast);
    for (int b = 0; b < (1 << N); ++b)
      ASSERT_EQ(fast[b], cube.sub_cube(b, margins[b]).distance2_to(q))
          << "case " << t << " sub-cube " << b;
  }
}

TEST(SpaceTree, SubCubeDistancesEqualEachSubCubesOwn) {
  check_sub_cube_distances<1>(31);
  check_sub_cube_distances<2>(32);
  check_sub_cube_distances<3>(33);
}

TEST(SpaceTree, DefaultBucketOfPointsIs64) {
  // 65 points in distinct octants of a cube split its root (64 held, the 65th splits); 64 do not.
  Points<3> pts;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 65; ++i) pts.push_back({u(rng), u(rng), u(rng)});
  const auto adaptor = adaptor_of<3>(pts);
  const auto all = SpaceTree<3, decltype(adaptor)>::with_all(adaptor);
  EXPECT_GT(all.cube_count(), 1u);
  EXPECT_EQ(all.check(), "");
  const auto first64 = points_adaptor<3>(64, [&pts](std::size_t i, int k) { return pts[i][k]; });
  EXPECT_EQ((SpaceTree<3, decltype(first64)>::with_all(first64).cube_count()), 1u);
}

TEST(SpaceTree, InsertRemoveSequencesKeepInvariants) {
  Points<3> pts = make_cloud<3>(Cloud::Blobs, 3000, 31);
  // Some duplicates and far outliers (the root must grow).
  for (int i = 0; i < 40; ++i) pts.push_back(pts[i]);
  pts.push_back({1e3, -1e3, 5e2});
  pts.push_back({-1e4, 2, 3});
  const auto adaptor = adaptor_of<3>(pts);
  SpaceTree<3, decltype(adaptor)> tree(adaptor, {.bucket = 4});
  std::mt19937_64 rng(32);
  std::uniform_int_distribution<std::uint32_t> pick(0, pts.size() - 1);
  std::vector<bool> held(pts.size(), false);
  std::size_t count = 0;
  for (int op = 0; op < 6000; ++op) {
    const std::uint32_t id = pick(rng);
    if (held[id]) {
      ASSERT_TRUE(tree.remove(id));
      --count;
    } else {
      tree.insert(id);
      ++count;
    }
    held[id] = !held[id];
    // Re-laying the cubes out (free slots dropped, cubes renumbered) keeps every invariant.
    if (op % 700 == 350) tree.lay_out_depth_first();
    ASSERT_EQ(tree.size(), count);
    ASSERT_EQ(tree.check(), "") << "after operation " << op;
    ASSERT_EQ(tree.contains(id), held[id]);
    // The nearest and the 5 nearest held points equal brute force over the held points, both
    // when the searches read the coordinate columns (just laid out) and when an insert or
    // remove since has left them to the cubes' object records.
    if ((op % 500 == 0 || op % 700 == 350) && count > 0) {
      const std::array<double, 3> q{0.5, 0.5, 0.5};
      std::vector<double> held_d2;
      for (std::size_t i = 0; i < pts.size(); ++i)
        if (held[i]) held_d2.push_back(dist2<3>(q, pts[i]));
      std::sort(held_d2.begin(), held_d2.end());
      ASSERT_EQ(nearest<3>(tree, q).distance, std::sqrt(held_d2[0])) << "after operation " << op;
      const auto knn = k_nearest<3>(tree, q, 5);
      ASSERT_EQ(knn.size(), std::min<std::size_t>(5, count));
      for (std::size_t j = 0; j < knn.size(); ++j)
        ASSERT_EQ(knn[j].distance, std::sqrt(held_d2[j])) << "after operation " << op;
    }
  }
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    if (held[i]) {
      ASSERT_TRUE(tree.remove(i));
    }
  }
  EXPECT_EQ(tree.size(), 0u);
  EXPECT_EQ(tree.check(), "");
  EXPECT_FALSE(tree.remove(0));
  // Memory follows the objects held: an emptied tree keeps no cubes.
  EXPECT_EQ(tree.cube_count(), 0u);
}

TEST(SpaceTree, CheckFindsAnObjectMovedWithoutReinsertion) {
  // The tree keeps each object's box from its insertion; moving a point behind its back is a
  // misuse check() must name.
  Points<3> pts = make_cloud<3>(Cloud::Uniform, 200, 7);
  const auto adaptor = adaptor_of<3>(pts);
  auto tree = SpaceTree<3, decltype(adaptor)>::with_all(adaptor);
  ASSERT_EQ(tree.check(), "");
  pts[17][1] += 1e-9;
  EXPECT_NE(tree.check().find("object 17 in cube"), std::string::npos) << tree.check();
  ASSERT_TRUE(tree.remove(17));
  tree.insert(17);
  EXPECT_EQ(tree.check(), "");
}

TEST(SpaceTree, InlineVectorSpillsToTheHeap) {
  InlineVector<int, 4> v;
  std::vector<int> expected;
  for (int i = 0; i < 1000; ++i) {
    v.push_back(3 * i);
    expected.push_back(3 * i);
    if (i % 7 == 6) {
      v.pop_back();
      expected.pop_back();
    }
  }
  ASSERT_EQ(v.size(), expected.size());
  EXPECT_TRUE(std::equal(v.begin(), v.end(), expected.begin()));
  EXPECT_EQ(v.back(), expected.back());
  v.clear();
  EXPECT_TRUE(v.empty());
}

TEST(SpaceTree, RejectsNonFiniteAndDoubleInsert) {
  Points<2> pts{{0, 0}, {std::nan(""), 1}};
  const auto adaptor = adaptor_of<2>(pts);
  SpaceTree<2, decltype(adaptor)> tree(adaptor);
  tree.insert(0);
  EXPECT_THROW(tree.insert(0), InputError);
  EXPECT_THROW(tree.insert(1), InputError);
  EXPECT_THROW(tree.insert(2), InputError);
}

}  // namespace
}  // namespace shockfield::geometry
