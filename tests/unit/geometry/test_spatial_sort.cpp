// The Delaunay insertion order (geometry/spatial_sort.hpp): the Hilbert index is a bijection of
// the grid onto 0 .. 2^(N·bits) − 1 whose consecutive indices are neighbouring cells (one step
// along one axis — the defining property of a Hilbert curve), and the BRIO order is a
// permutation of the ids given whose rounds (halves, from the end) are each in Hilbert order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>

#include "shockfield/geometry/spatial_sort.hpp"

namespace shockfield::geometry {
namespace {

template <int N>
void check_hilbert_curve(int bits) {
  const std::uint32_t side = 1u << bits;
  std::map<std::uint64_t, std::array<std::uint32_t, N>> cell_of;
  std::array<std::uint32_t, N> c{};
  for (std::uint64_t flat = 0; flat < std::uint64_t{1} << (N * bits); ++flat) {
    for (int k = 0; k < N; ++k) c[k] = static_cast<std::uint32_t>(flat >> (k * bits)) % side;
    const std::uint64_t h = hilbert_index<N>(c, bits);
    ASSERT_LT(h, std::uint64_t{1} << (N * bits));
    ASSERT_TRUE(cell_of.emplace(h, c).second) << "index " << h << " given twice";
  }
  for (auto it = std::next(cell_of.begin()); it != cell_of.end(); ++it) {
    int steps = 0;
    for (int k = 0; k < N; ++k)
      steps += std::abs(static_cast<int>(it->second[k]) - static_cast<int>(std::prev(it)->second[k]));
    ASSERT_EQ(steps, 1) << "indices " << it->first - 1 << " and " << it->first << " are not neighbours";
  }
}

TEST(SpatialSort, HilbertIndexIsACurveThroughNeighbouringCells) {
  check_hilbert_curve<2>(5);
  check_hilbert_curve<3>(4);
}

TEST(SpatialSort, BrioRoundsArePermutationsInHilbertOrder) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 5.0);
  std::vector<std::array<double, 3>> pts(5000);
  for (auto& p : pts) p = {u(rng), u(rng), 0.25 * u(rng)};
  std::vector<std::int32_t> ids;
  for (std::int32_t i = 0; i < 5000; i += 2) ids.push_back(i);  // every other point
  const auto order = brio_hilbert_order<3>(pts, ids);
  auto sorted = order;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(sorted, ids);
  // The same grid as brio_hilbert_order: 2^21 cells across the bounding box of the ids' points.
  std::array<double, 3> lo, hi;
  lo.fill(1e300);
  hi.fill(-1e300);
  for (std::int32_t i : ids)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], pts[i][k]);
      hi[k] = std::max(hi[k], pts[i][k]);
    }
  auto key = [&](std::int32_t i) {
    std::array<std::uint32_t, 3> c;
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<std::uint32_t>((pts[i][k] - lo[k]) * 0x1p21 * (1.0 - 0x1p-40) / (hi[k] - lo[k]));
    return hilbert_index<3>(c, 21);
  };
  std::size_t rounds = 0;
  for (std::size_t end = order.size(); end > 0; ++rounds) {
    const std::size_t begin = end > 64 ? end / 2 : 0;
    for (std::size_t j = begin + 1; j < end; ++j) {
      ASSERT_LE(key(order[j - 1]), key(order[j]));
    }
    // A round is not one Hilbert sweep of everything: its first key is below the previous
    // round's last (the rounds restart the curve).
    if (end < order.size()) {
      EXPECT_GT(key(order[end - 1]), key(order[end]));
    }
    end = begin;
  }
  EXPECT_EQ(rounds, 7u);  // 2500 ids: rounds from 1250, 625, 312, 156, 78, 39 and 0
}

}  // namespace
}  // namespace shockfield::geometry
