// All thresholds in one pass equal one pass per threshold, bit for bit (the block sums of the
// functionals' weights, the configuration counts, and the functionals), in 2D and 3D, for both
// boundaries, with void cells, for 1 and 2 threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <random>

#include "shockfield/analysis/minkowski.hpp"

namespace sa = shockfield::analysis;

namespace {

sa::GridField random_field(std::size_t nx, std::size_t ny, std::size_t nz, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  auto f = sa::GridField::filled(nx, ny, nz, 0.0);
  for (auto& v : f.values) v = std::round(g(rng) * 8.0) / 8.0;  // ties with thresholds
  f.is_void.assign(f.size(), 0);
  for (std::size_t i = 0; i < f.size(); i += 17) f.is_void[i] = 1;
  return f;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Weights that count the configurations themselves (row c: 1 in column c).
sa::BlockWeights one_hot(int dimension) {
  const std::size_t n = sa::configurations(dimension);
  sa::BlockWeights w{dimension, n, std::vector<std::int32_t>(n * n, 0)};
  for (std::size_t c = 0; c < n; ++c) w.values[c * n + c] = 1;
  return w;
}

void expect_equal_rows(const sa::BlockSums& all, std::size_t k, const sa::BlockSums& one) {
  ASSERT_EQ(one.width, all.width);
  EXPECT_TRUE(std::equal(one.sums.begin(), one.sums.end(), all.row(k).begin()))
      << "threshold " << all.thresholds[k];
}

void check(const sa::GridField& f, sa::Boundary boundary) {
  std::vector<double> t;
  for (int k = -24; k <= 24; ++k) t.push_back(k / 8.0);  // includes values equal to cell values
  t.push_back(1e9);
  t.insert(t.begin(), -1e9);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const auto& weights = sa::minkowski_weights(f.dimension());
    const auto configs = one_hot(f.dimension());
    const auto all = sa::sum_block_weights(f, t, boundary, weights);
    const auto all_configs = sa::sum_block_weights(f, t, boundary, configs);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const auto one = sa::sum_block_weights(f, t[k], boundary, weights);
      expect_equal_rows(all, k, one);
      expect_equal_rows(all_configs, k, sa::sum_block_weights(f, t[k], boundary, configs));
      if (f.dimension() == 2) {
        for (auto c : {sa::Connectivity2D::four, sa::Connectivity2D::eight}) {
          const auto a = sa::functionals_2d(all, k, f, c), b = sa::functionals_2d(one, 0, f, c);
          EXPECT_TRUE(same_bits(a.boundary_length, b.boundary_length));
          EXPECT_TRUE(same_bits(a.area_fraction, b.area_fraction));
          EXPECT_EQ(a.euler, b.euler);
        }
      } else {
        for (auto c : {sa::Adjacency3D::six_26, sa::Adjacency3D::twentysix_6}) {
          const auto a = sa::functionals_3d(all, k, f, c), b = sa::functionals_3d(one, 0, f, c);
          EXPECT_TRUE(same_bits(a.surface_area, b.surface_area));
          EXPECT_TRUE(same_bits(a.mean_breadth, b.mean_breadth));
          EXPECT_EQ(a.euler, b.euler);
        }
      }
    }
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace

TEST(OnePass, EqualsPerThreshold2D) {
  const auto f = random_field(37, 29, 1, 1);
  check(f, sa::Boundary::open);
  check(f, sa::Boundary::periodic);
}

TEST(OnePass, EqualsPerThreshold3D) {
  const auto f = random_field(13, 11, 9, 2);
  check(f, sa::Boundary::open);
  check(f, sa::Boundary::periodic);
}

TEST(OnePass, RowsSumToBlockCount) {
  const auto f = random_field(20, 15, 1, 3);
  const std::vector<double> t{-1.0, 0.0, 1.0};
  for (auto b : {sa::Boundary::open, sa::Boundary::periodic}) {
    const auto all = sa::sum_block_weights(f, t, b, one_hot(2));
    for (std::size_t k = 0; k < t.size(); ++k) {
      std::int64_t sum = 0;
      for (auto c : all.row(k)) sum += c;
      EXPECT_EQ(sum, sa::block_count(f, b));
    }
  }
}

// Weights of ±2^15 make the 32-bit per-thread accumulators flush every 32767 blocks, within rows
// longer than that: the sums must still equal 2^15 × the configuration counts.
TEST(OnePass, LargeWeightsFlushBeforeOverflow) {
  const auto f = random_field(40000, 3, 1, 4);
  const std::vector<double> t{-0.5, 0.0, 0.5};
  auto big = one_hot(2);
  for (auto& v : big.values) v *= -(1 << 15);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const auto counts = sa::sum_block_weights(f, t, sa::Boundary::open, one_hot(2));
    const auto all = sa::sum_block_weights(f, t, sa::Boundary::open, big);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const auto one = sa::sum_block_weights(f, t[k], sa::Boundary::open, big);
      for (std::size_t c = 0; c < 16; ++c) {
        EXPECT_EQ(all.row(k)[c], -(std::int64_t{1} << 15) * counts.row(k)[c]);
        EXPECT_EQ(one.sums[c], all.row(k)[c]);
      }
    }
  }
  omp_set_num_threads(omp_get_num_procs());
}
