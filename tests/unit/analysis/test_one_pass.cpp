// All thresholds in one pass equal one pass per threshold, bit for bit (configuration counts
// and functionals), in 2D and 3D, for both boundaries, with void cells, for 1 and 2 threads.
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

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void check(const sa::GridField& f, sa::Boundary boundary) {
  std::vector<double> t;
  for (int k = -24; k <= 24; ++k) t.push_back(k / 8.0);  // includes values equal to cell values
  t.push_back(1e9);
  t.insert(t.begin(), -1e9);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const auto all = sa::count_configurations(f, t, boundary);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const auto one = sa::count_configurations(f, t[k], boundary);
      ASSERT_TRUE(std::equal(one.counts.begin(), one.counts.end(), all.row(k).begin()))
          << "threshold " << t[k];
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
    const auto all = sa::count_configurations(f, t, b);
    for (std::size_t k = 0; k < t.size(); ++k) {
      std::int64_t sum = 0;
      for (auto c : all.row(k)) sum += c;
      EXPECT_EQ(sum, sa::block_count(f, b));
    }
  }
}
