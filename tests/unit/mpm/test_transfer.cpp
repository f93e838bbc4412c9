// The particle-to-grid scatter of mpm::Transfer (slab passes, periodic wrap-round slabs) against a
// plain serial sum of the shape functions, in 2D and 3D, on grids periodic along the outermost
// axis with an odd number of node layers (the case where slabs reach round the end), and its
// bitwise independence of the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/simulation.hpp"
#include "shockfield/mpm/transfer.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

mpm::GridSpec periodic_grid(int dim, std::array<int, 3> cells) {
  mpm::GridSpec g;
  g.dim = dim;
  g.cell_size = Vec3(1e-6, 1e-6, 1e-6);
  g.cells = cells;
  g.periodic = {true, true, dim == 3};
  return g;
}

// Random points over the whole periodic box, random velocities and stresses.
mpm::Particles random_points(const mpm::GridSpec& g, int count) {
  const auto al = materials::aluminium_seed000();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  mpm::Particles p;
  for (int q = 0; q < count; ++q) {
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    for (int a = 0; a < g.dim; ++a) x[a] = u(rng) * g.length(a), v[a] = 100.0 * (u(rng) - 0.5);
    p.add(x, v, 1e-13 * (0.5 + u(rng)), Vec3::Constant(0.2e-6), al, 0);
    p.state.back().pressure = 1e9 * (u(rng) - 0.5);
    p.state.back().deviatoric.s(0, 1) = p.state.back().deviatoric.s(1, 0) = 1e8 * (u(rng) - 0.5);
  }
  return p;
}

// m_i, (mv)_i and f_i summed particle by particle straight from the shape functions.
void reference_sums(const mpm::Grid& grid, const mpm::Particles& p, std::vector<double>& m, std::vector<Vec3>& mv,
                    std::vector<Vec3>& f) {
  const auto& g = grid.spec();
  m.assign(grid.size(), 0.0), mv.assign(grid.size(), Vec3::Zero()), f.assign(grid.size(), Vec3::Zero());
  for (std::size_t q = 0; q < p.size(); ++q) {
    std::array<mpm::Weights1D, 3> w{};
    for (int a = 0; a < g.dim; ++a) {
      w[static_cast<std::size_t>(a)] =
          mpm::GimpShape::evaluate(p.x[q][a] - g.origin[a], g.cell_size[a], p.half_size[q][a]);
      ASSERT_TRUE(grid.fit(a, w[static_cast<std::size_t>(a)]));
    }
    const Mat3 vs = p.volume(q) * p.state[q].stress();
    for (int c = 0; c < w[2].count; ++c)
      for (int b = 0; b < w[1].count; ++b)
        for (int a = 0; a < w[0].count; ++a) {
          const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b), uc = static_cast<std::size_t>(c);
          const double n = w[0].w[ua] * w[1].w[ub] * w[2].w[uc];
          const Vec3 grad(w[0].dw[ua] * w[1].w[ub] * w[2].w[uc], w[0].w[ua] * w[1].dw[ub] * w[2].w[uc],
                          w[0].w[ua] * w[1].w[ub] * w[2].dw[uc]);
          const std::size_t i = grid.flat(grid.wrap(0, w[0].base + a), grid.wrap(1, w[1].base + b),
                                          grid.wrap(2, w[2].base + c));
          m[i] += n * p.mass[q];
          mv[i] += n * p.mass[q] * p.v[q];
          f[i] -= vs * grad;
        }
  }
}

void check_scatter(int dim, std::array<int, 3> cells) {
  const mpm::GridSpec spec = periodic_grid(dim, cells);
  const mpm::Particles p = random_points(spec, 400);
  std::vector<double> m;
  std::vector<Vec3> mv, f;
  mpm::Grid ref(spec);
  reference_sums(ref, p, m, mv, f);
  auto scatter = [&](int threads) {
    omp_set_num_threads(threads);
    mpm::Grid grid(spec);
    mpm::Transfer t;
    t.build(grid, p, mpm::ShapeKind::Gimp);
    t.to_grid(grid, p);
    omp_set_num_threads(1);
    return grid;
  };
  const mpm::Grid one = scatter(1), two = scatter(2);
  double mass_scale = 0, momentum_scale = 0, force_scale = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    mass_scale = std::max(mass_scale, m[i]);
    momentum_scale = std::max(momentum_scale, mv[i].norm());
    force_scale = std::max(force_scale, f[i].norm());
  }
  for (std::size_t i = 0; i < ref.size(); ++i) {
    EXPECT_NEAR(one.mass[i], m[i], 1e-12 * mass_scale) << i;
    EXPECT_LT((one.momentum[i] - mv[i]).norm(), 1e-12 * momentum_scale) << i;
    EXPECT_LT((one.force[i] - f[i]).norm(), 1e-12 * force_scale) << i;
    ASSERT_EQ(one.mass[i], two.mass[i]) << i;
    ASSERT_EQ(one.momentum[i], two.momentum[i]) << i;
    ASSERT_EQ(one.force[i], two.force[i]) << i;
  }
}

}  // namespace

TEST(TransferScatter, MatchesSerialSums2DPeriodicOddLayers) { check_scatter(2, {4, 7, 0}); }
TEST(TransferScatter, MatchesSerialSums2DPeriodicTwoLayers) { check_scatter(2, {3, 2, 0}); }
TEST(TransferScatter, MatchesSerialSums3DPeriodicOddLayers) { check_scatter(3, {3, 3, 5}); }

TEST(TransferScatter, ZVelocityIn2DIsAnInputError) {
  const auto al = materials::aluminium_seed000();
  const mpm::GridSpec spec = periodic_grid(2, {4, 4, 0});
  mpm::Particles p;
  p.add(Vec3(1e-6, 1e-6, 0), Vec3(0, 0, 5.0), 1e-13, Vec3::Constant(0.2e-6), al, 0);
  EXPECT_THROW(mpm::Simulation(spec, {al}, std::move(p)), InputError);
}
