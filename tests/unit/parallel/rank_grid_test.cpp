// The decomposition layer on one rank (both builds): rank grid choice and checks, the block split,
// the periodic halo of a one-rank axis, gather/scatter and the ordered sum.
#include <gtest/gtest.h>

#include <numeric>

#include "shockfield/core/error.hpp"
#include "shockfield/parallel/block_transfer.hpp"
#include "shockfield/parallel/halo_exchange.hpp"
#include "shockfield/parallel/ordered_sum.hpp"
#include "shockfield/parallel/rank_grid.hpp"

namespace shockfield::parallel {
namespace {

TEST(RankGrid, SplitCoversTheAxisWithSizesDifferingByOne) {
  long long next = 0;
  for (int p = 0; p < 7; ++p) {
    const Block b = split_axis(100, 7, p);
    EXPECT_EQ(b.begin[0], next);
    EXPECT_TRUE(b.count[0] == 14 || b.count[0] == 15);
    next += b.count[0];
  }
  EXPECT_EQ(next, 100);
}

TEST(RankGrid, ChoosesTheGridWithTheLeastHalo) {
  // A 1D tube is cut along x only; a 512 x 64 strip along x; a square of 16 ranks along both
  // axes (4 x 4 blocks exchange 2·128 + 2·128 cells per layer, 2 x 8 ones 2·64 + 2·256); a cube
  // of 64 ranks along all three. On a tie (512², 4 ranks: 1 x 4 strips and 2 x 2 squares both
  // exchange 1024 cells per layer) the first found wins: fewer cuts along x.
  EXPECT_EQ(choose_rank_grid({400, 1, 1}, 4, 2), (Dims3{4, 1, 1}));
  EXPECT_EQ(choose_rank_grid({512, 64, 1}, 4, 2), (Dims3{4, 1, 1}));
  EXPECT_EQ(choose_rank_grid({512, 512, 1}, 16, 2), (Dims3{4, 4, 1}));
  EXPECT_EQ(choose_rank_grid({64, 64, 64}, 64, 2), (Dims3{4, 4, 4}));
  EXPECT_EQ(choose_rank_grid({512, 512, 1}, 4, 2), (Dims3{1, 4, 1}));
  EXPECT_EQ(choose_rank_grid({10, 1, 1}, 1, 2), (Dims3{1, 1, 1}));
}

TEST(RankGrid, RefusesMoreRanksThanTheStencilAllows) {
  // 10 cells with 2 ghost layers: at most 5 blocks.
  EXPECT_EQ(choose_rank_grid({10, 1, 1}, 5, 2), (Dims3{5, 1, 1}));
  try {
    choose_rank_grid({10, 1, 1}, 6, 2);
    FAIL() << "6 ranks on 10 cells accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("use at most 5 ranks"), std::string::npos) << e.what();
  }
  // 7 ranks do not factor onto 10 x 10 (7 > 5 blocks along either axis).
  EXPECT_THROW(choose_rank_grid({10, 10, 1}, 7, 2), InputError);
}

TEST(RankGrid, RefusesAGivenGridThatDoesNotMatch) {
  EXPECT_NO_THROW(check_rank_grid({2, 2, 1}, {100, 100, 1}, 4, 2));
  try {
    check_rank_grid({3, 1, 1}, {100, 1, 1}, 4, 2);
    FAIL() << "3 x 1 x 1 accepted for 4 ranks";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has 3 ranks, the run has 4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_rank_grid({1, 2, 1}, {100, 1, 1}, 2, 2), InputError);  // y has one cell
  EXPECT_THROW(check_rank_grid({0, 1, 1}, {100, 1, 1}, 0, 2), InputError);
}

GridLayout layout_2d(int nx, int ny, int ghosts, int components) {
  GridLayout l{{nx, ny, 1}, {ghosts, ghosts, 0}, components, 0};
  l.component_stride = l.cells();
  return l;
}

TEST(HaloExchange, OneRankPeriodicAxisWrapsAndANonPeriodicOneIsLeftAlone) {
  const Communicator world = Communicator::world();
  if (world.size() != 1) GTEST_SKIP() << "one-rank test";
  const RankGrid grid(world, {1, 1, 1}, {true, false, false}, {5, 4, 1}, 2);
  const GridLayout l = layout_2d(5, 4, 2, 2);
  std::vector<double> f(2 * l.cells(), -1.0);
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) f[c * l.cells() + l.at(i, j, 0)] = 1000 * c + 10 * j + i;
  const HaloExchange halo(grid.comm(), l);
  EXPECT_TRUE(halo.has_neighbour(0, 0) && halo.has_neighbour(0, 1));
  EXPECT_FALSE(halo.has_neighbour(1, 0) || halo.has_neighbour(1, 1));
  halo.exchange(f.data(), 0);
  halo.exchange(f.data(), 1);
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < 4; ++j) {
      EXPECT_EQ(f[c * l.cells() + l.at(-2, j, 0)], 1000 * c + 10 * j + 3);
      EXPECT_EQ(f[c * l.cells() + l.at(-1, j, 0)], 1000 * c + 10 * j + 4);
      EXPECT_EQ(f[c * l.cells() + l.at(5, j, 0)], 1000 * c + 10 * j + 0);
      EXPECT_EQ(f[c * l.cells() + l.at(6, j, 0)], 1000 * c + 10 * j + 1);
    }
  EXPECT_EQ(f[l.at(0, -1, 0)], -1.0);  // y is not periodic: the method's boundary fills it
  EXPECT_EQ(f[l.at(0, 4, 0)], -1.0);
  EXPECT_EQ(halo.doubles_per_exchange(), 2u * 2u * 2u * 4u);  // 2 faces x 2 layers x 2 components x 4 rows
}

TEST(BlockTransfer, GatherAndScatterOfOneBlockCopyTheInterior) {
  const Communicator world = Communicator::world();
  if (world.size() != 1) GTEST_SKIP() << "one-rank test";
  const RankGrid grid(world, {1, 1, 1}, {false, false, false}, {3, 2, 1}, 2);
  const GridLayout l = layout_2d(3, 2, 2, 1);
  std::vector<double> local(l.cells(), 0.0), global(l.cells(), 0.0), back(l.cells(), 0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) local[l.at(i, j, 0)] = 1 + i + 3 * j;
  gather_blocks(grid, l, local.data(), l, global.data());
  EXPECT_EQ(global, local);
  scatter_blocks(grid, l, global.data(), l, back.data());
  EXPECT_EQ(back, local);
}

TEST(OrderedSum, AddsInGlobalIndexOrder) {
  const Communicator world = Communicator::world();
  if (world.size() != 1) GTEST_SKIP() << "one-rank test";
  // Items given out of order: the sum is the in-order sum, which differs in its last bits from
  // the given order's (1e16 + 1 - 1e16 ...).
  const std::vector<double> values{1.0, 1e16, -1e16, 1.0};
  const std::vector<long long> index{3, 0, 1, 2};
  const double in_order = ((1e16 + -1e16) + 1.0) + 1.0;
  EXPECT_EQ(ordered_sum(world, values, index, 1)[0], in_order);
  EXPECT_NE(std::accumulate(values.begin(), values.end(), 0.0), in_order);
  EXPECT_THROW(ordered_sum(world, values, {0, 0, 1, 2}, 1), std::logic_error);
}

}  // namespace
}  // namespace shockfield::parallel
