// The filtered predicates against a brute-force big-integer evaluation of the un-translated
// determinants (exact_reference.hpp): random points, near-degenerate points (where the
// floating-point stage cannot decide), exactly degenerate points (lattice points on a sphere, on
// a plane), and the symbolic perturbation's rule. Tolerance: none — signs must agree exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shockfield/geometry/predicates.hpp"
#include "unit/geometry/exact_reference.hpp"

namespace shockfield::geometry {
namespace {

using test::reference_in_sphere;
using test::reference_orient;

/// A double rounded to a multiple of 2^−40, so that every test coordinate is exactly an integer
/// times 2^−64 (test::kShift) with room for the 2^−53 perturbations added to it.
double on_grid(double x) { return std::ldexp(std::round(std::ldexp(x, 40)), -40); }

template <int N>
std::array<double, N> random_point(std::mt19937_64& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  std::array<double, N> p;
  for (double& x : p) x = on_grid(u(rng));
  return p;
}

template <int N, std::size_t M>
std::array<const double*, M> refs(const std::array<std::array<double, N>, M>& pts) {
  std::array<const double*, M> r;
  for (std::size_t i = 0; i < M; ++i) r[i] = pts[i].data();
  return r;
}

template <int N>
void check_random(int trials) {
  std::mt19937_64 rng(7 + N);
  for (int t = 0; t < trials; ++t) {
    std::array<std::array<double, N>, N + 2> pts;
    for (auto& p : pts) p = random_point<N>(rng);
    const auto r = refs<N>(pts);
    std::array<const double*, N + 1> o;
    std::copy(r.begin(), r.begin() + N + 1, o.begin());
    ASSERT_EQ(orient<N>(o), reference_orient<N>(o)) << "trial " << t;
    ASSERT_EQ(in_sphere<N>(r), reference_in_sphere<N>(r)) << "trial " << t;
  }
}

TEST(Predicates, RandomPointsAgreeWithBigIntegerReference) {
  check_random<2>(3000);
  check_random<3>(1500);
}

// Points on dyadic grids (integers m·2^shift), the input of the predicates' integer stage
// (predicates_grid.hpp; exact lattices): small grids, where most determinants are exactly zero,
// differences up to 2^23 (the 128-bit evaluation) and just past it (320 bits), at three scales,
// then coordinates spanning 59 bits (320 bits) and 62 bits (past the stage: expansions). Signs
// must equal the big-integer reference's.
template <int N>
void check_dyadic_grid(std::int64_t half_width, int shift, int trials) {
  std::mt19937_64 rng(31 + N + shift);
  std::uniform_int_distribution<std::int64_t> m(-half_width, half_width);
  int zeros = 0;
  for (int t = 0; t < trials; ++t) {
    std::array<std::array<double, N>, N + 2> pts;
    for (auto& p : pts)
      for (double& x : p) x = std::ldexp(static_cast<double>(m(rng)), shift);
    const auto r = refs<N>(pts);
    std::array<const double*, N + 1> o;
    std::copy(r.begin(), r.begin() + N + 1, o.begin());
    ASSERT_EQ(orient<N>(o), reference_orient<N>(o)) << "trial " << t << " width " << half_width;
    const int s = in_sphere<N>(r);
    ASSERT_EQ(s, reference_in_sphere<N>(r)) << "trial " << t << " width " << half_width;
    zeros += s == 0;
  }
  if (half_width <= 2) {
    EXPECT_GT(zeros, trials / 20) << "the small grid should be degenerate";
  }
}

TEST(Predicates, DyadicGridPointsAgreeWithBigIntegerReference) {
  for (const int shift : {-40, -1, 20})
    for (const std::int64_t half_width : {std::int64_t{2}, std::int64_t{1} << 22,
                                          (std::int64_t{1} << 23) + 1}) {
      check_dyadic_grid<2>(half_width, shift, 400);
      check_dyadic_grid<3>(half_width, shift, 300);
    }
  for (const std::int64_t half_width : {std::int64_t{1} << 59, std::int64_t{1} << 62}) {
    check_dyadic_grid<2>(half_width, -40, 400);
    check_dyadic_grid<3>(half_width, -40, 300);
  }
}

TEST(Predicates, InsideMeansPositiveForPositivelyOrientedSimplex) {
  const std::array<double, 2> a{0, 0}, b{1, 0}, c{0, 1}, in{0.25, 0.25}, out{2, 2};
  EXPECT_EQ(orient<2>({a.data(), b.data(), c.data()}), 1);
  EXPECT_EQ(in_sphere<2>({a.data(), b.data(), c.data(), in.data()}), 1);
  EXPECT_EQ(in_sphere<2>({a.data(), b.data(), c.data(), out.data()}), -1);
  const std::array<double, 3> p0{0, 0, 0}, p1{0, 1, 0}, p2{1, 0, 0}, p3{0, 0, 1};
  const std::array<double, 3> centre{0.2, 0.2, 0.2}, far{3, 3, 3};
  EXPECT_EQ(orient<3>({p0.data(), p1.data(), p2.data(), p3.data()}), 1);
  EXPECT_EQ(in_sphere<3>({p0.data(), p1.data(), p2.data(), p3.data(), centre.data()}), 1);
  EXPECT_EQ(in_sphere<3>({p0.data(), p1.data(), p2.data(), p3.data(), far.data()}), -1);
}

// Kettner et al. (2008)'s classroom example: orient of p = (0.5 + i u, 0.5 + j u) against
// q = (12, 12), r = (24, 24) with u = 2^−53; naive floating point gets a noisy sign pattern here.
TEST(Predicates, NearlyCollinearGridMatchesReference) {
  const double u = std::ldexp(1.0, -53);
  const std::array<double, 2> q{12, 12}, r{24, 24};
  int zeros = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const std::array<double, 2> p{0.5 + i * u, 0.5 + j * u};
      const std::array<const double*, 3> pts{p.data(), q.data(), r.data()};
      const int s = orient<2>(pts);
      ASSERT_EQ(s, reference_orient<2>(pts)) << i << ", " << j;
      zeros += s == 0;
    }
  EXPECT_GT(zeros, 0);  // the exactly collinear ones are found
}

// Points rounded from a sphere / a plane and then moved by a few ulps: the filter cannot decide.
TEST(Predicates, NearlyCosphericalAndCoplanarMatchReference) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  const double u = std::ldexp(1.0, -52);
  std::uniform_int_distribution<int> ulps(-2, 2);
  for (int t = 0; t < 1500; ++t) {
    std::array<std::array<double, 3>, 5> s;
    for (auto& p : s) {
      const double x = g(rng), y = g(rng), z = g(rng), n = std::sqrt(x * x + y * y + z * z);
      p = {on_grid(x / n) + ulps(rng) * u, on_grid(y / n) + ulps(rng) * u,
           on_grid(z / n) + ulps(rng) * u};
    }
    const auto r = refs<3>(s);
    ASSERT_EQ(in_sphere<3>(r), reference_in_sphere<3>(r)) << "trial " << t;
    // Coplanar: the fourth point on the plane of the first three, plus a few ulps.
    std::array<std::array<double, 3>, 4> c{s[0], s[1], s[2], {}};
    const double a = 0.3, b = 0.45;
    for (int k = 0; k < 3; ++k)
      c[3][k] = on_grid(s[0][k] + a * (s[1][k] - s[0][k]) + b * (s[2][k] - s[0][k])) +
                ulps(rng) * u;
    const auto cr = refs<3>(c);
    ASSERT_EQ(orient<3>(cr), reference_orient<3>(cr)) << "trial " << t;
    // 2D: four points near a circle.
    std::array<std::array<double, 2>, 4> q;
    for (int i = 0; i < 4; ++i) q[i] = {s[i][0] / 2 + ulps(rng) * u, s[i][1] / 2};
    const auto qr = refs<2>(q);
    ASSERT_EQ(in_sphere<2>(qr), reference_in_sphere<2>(qr)) << "trial " << t;
  }
}

TEST(Predicates, ExactDegeneraciesGiveZeroAndPerturbationDecides) {
  // Six vertices of an octahedron are cospherical; any five give in_sphere == 0.
  const std::array<std::array<double, 3>, 6> o{
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}};
  const std::array<const double*, 5> five{o[0].data(), o[1].data(), o[2].data(), o[3].data(),
                                          o[5].data()};
  EXPECT_EQ(in_sphere<3>(five), 0);
  EXPECT_EQ(in_sphere_exact<3>(five), 0);
  // The rule: the first non-zero (−1)^{i+3} orient(rest_i) in increasing rank.
  const std::array<std::int64_t, 5> ranks{0, 1, 2, 3, 5};
  const int s = in_sphere_perturbed<3>(five, ranks);
  EXPECT_NE(s, 0);
  const std::array<const double*, 4> rest0{o[1].data(), o[2].data(), o[3].data(), o[5].data()};
  const int o0 = reference_orient<3>(rest0);
  ASSERT_NE(o0, 0);
  EXPECT_EQ(s, -o0);  // i = 0: (−1)^3
  // The query point (last) ranked first: its own term −orient(simplex) decides, i.e. the point
  // counts as outside the sphere of a positively oriented simplex.
  const std::array<std::int64_t, 5> query_first{1, 2, 3, 4, 0};
  const std::array<const double*, 4> simplex{o[0].data(), o[1].data(), o[2].data(), o[3].data()};
  EXPECT_EQ(in_sphere_perturbed<3>(five, query_first), -orient<3>(simplex));
  // Lattice points on the circle x² + y² = 25 in 2D.
  const std::array<std::array<double, 2>, 4> c{{{5, 0}, {3, 4}, {0, 5}, {-4, -3}}};
  EXPECT_EQ(in_sphere<2>(refs<2>(c)), 0);
  EXPECT_NE(in_sphere_perturbed<2>(refs<2>(c), {0, 1, 2, 3}), 0);
  // Coplanar 3D and collinear 2D points.
  const std::array<std::array<double, 3>, 4> plane{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 7, 0}}};
  EXPECT_EQ(orient<3>(refs<3>(plane)), 0);
  const std::array<std::array<double, 2>, 3> line{{{1, 1}, {2, 2}, {1e10, 1e10}}};
  EXPECT_EQ(orient<2>(refs<2>(line)), 0);
  // Everything in one plane: even the perturbed in-sphere is zero.
  const std::array<std::array<double, 3>, 5> flat{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 7, 0}, {2, 5, 0}}};
  EXPECT_EQ(in_sphere_perturbed<3>(refs<3>(flat), {0, 1, 2, 3, 4}), 0);
}

}  // namespace
}  // namespace shockfield::geometry
