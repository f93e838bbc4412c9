// Shape functions (Xu et al. 2015, eq. 9, GIMP), grid walls, and the sample builders of §4.1-4.2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/shape_functions.hpp"
#include "shockfield/mpm/simulation.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

// Partition of unity Σ N = 1 and Σ dN/dx = 0 (exact to round-off), and linear completeness
// Σ N·x_i = x, for both shape functions at many positions.
template <class S>
void check_shape(double half) {
  const double h = 0.7;
  for (int k = 0; k < 997; ++k) {
    const double x = 3.0 + 2.1 * h * k / 997.0;
    const mpm::Weights1D w = S::evaluate(x, h, half);
    double sum = 0, dsum = 0, first = 0;
    for (int i = 0; i < w.count; ++i) {
      sum += w.w[static_cast<std::size_t>(i)];
      dsum += w.dw[static_cast<std::size_t>(i)];
      first += w.w[static_cast<std::size_t>(i)] * (w.base + i) * h;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << x;
    EXPECT_NEAR(dsum, 0.0, 1e-12) << x;
    EXPECT_NEAR(first, x, 1e-12) << x;
  }
}

TEST(ShapeFunctions, LinearPartitionOfUnity) { check_shape<mpm::LinearShape>(0.0); }
TEST(ShapeFunctions, GimpPartitionOfUnity) { check_shape<mpm::GimpShape>(0.7 / 4); }

// GIMP is C1: its derivative is continuous across the kinks of the hat (check by finite differences).
TEST(ShapeFunctions, GimpDerivativeMatchesFiniteDifference) {
  const double h = 1.0, half = 0.25, d = 1e-6;
  for (double x : {0.1, 0.3, 0.5, 0.74, 0.76, 0.9}) {
    const auto a = mpm::GimpShape::evaluate(x - d, h, half), b = mpm::GimpShape::evaluate(x + d, h, half),
               c = mpm::GimpShape::evaluate(x, h, half);
    ASSERT_EQ(a.base, b.base);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR((b.w[i] - a.w[i]) / (2 * d), c.dw[i], 1e-5) << x << " " << i;
  }
}

// Porous body: voids do not overlap, lie inside the body, and the achieved porosity matches the
// target within the discretisation (±0.01 for ~300 points per void).
TEST(SampleBuilders, PorousBodyReachesTargetPorosity) {
  const auto al = materials::aluminium_seed000();
  const mpm::Body body{Vec3(0, 0, 0), Vec3(1e-3, 1e-3, 0), 2e-6, Vec3::Zero(), 0};
  const mpm::VoidSpec spec{0.1, 20e-6, 0.2, 7};
  const auto voids = mpm::place_voids(2, body, spec);
  for (std::size_t i = 0; i < voids.size(); ++i) {
    for (int a = 0; a < 2; ++a) {
      EXPECT_GE(voids[i].centre[a] - voids[i].radius, 0.0);
      EXPECT_LE(voids[i].centre[a] + voids[i].radius, 1e-3);
    }
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GE((voids[i].centre - voids[j].centre).norm(), voids[i].radius + voids[j].radius);
  }
  mpm::Particles p;
  const auto stats = mpm::add_body(p, 2, body, al, voids);
  EXPECT_NEAR(stats.porosity(), 0.1, 0.01);
  EXPECT_EQ(p.size(), stats.added);
  // Same seed, same sample.
  const auto again = mpm::place_voids(2, body, spec);
  ASSERT_EQ(again.size(), voids.size());
  EXPECT_EQ(again.back().centre, voids.back().centre);
}

TEST(SampleBuilders, PorousBody3D) {
  const mpm::Body body{Vec3(0, 0, 0), Vec3(1e-4, 1e-4, 1e-4), 2e-6, Vec3::Zero(), 0};
  const auto voids = mpm::place_voids(3, body, {0.05, 8e-6, 0.0, 3});
  mpm::Particles p;
  const auto stats = mpm::add_body(p, 3, body, materials::aluminium_seed000(), voids);
  EXPECT_NEAR(stats.porosity(), 0.05, 0.01);
}

TEST(SampleBuilders, ImpossiblePorosityIsAnInputError) {
  const mpm::Body body{Vec3(0, 0, 0), Vec3(1e-3, 1e-3, 0), 5e-6, Vec3::Zero(), 0};
  auto message = [&](const mpm::VoidSpec& spec) {
    try {
      mpm::place_voids(2, body, spec);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({0.6, 20e-6, 0.0, 1}).find("porosity"), std::string::npos);
  EXPECT_NE(message({0.1, 0.8e-3, 0.0, 1}).find("do not fit"), std::string::npos);
  EXPECT_NE(message({1e-6, 20e-6, 0.0, 1}).find("less than one void"), std::string::npos);
  // Below the jamming limit but too dense for random sequential addition of equal discs in a
  // small box: the packer gives up with the count it reached.
  EXPECT_NE(message({0.54, 100e-6, 0.0, 1}).find("could place only"), std::string::npos);
}

// Single cavity (seed §4.2.2: r = 5 µm at z = 10 µm): the removed points are the disc's area.
TEST(SampleBuilders, SingleCavityAtDepth) {
  const mpm::Body body{Vec3(-20e-6, 0, 0), Vec3(20e-6, 50e-6, 0), 0.5e-6, Vec3::Zero(), 0};
  const mpm::Void cavity = mpm::cavity_at(2, body, 10e-6, 5e-6);
  EXPECT_NEAR(cavity.centre[1], 10e-6, 1e-15);
  EXPECT_NEAR(cavity.centre[0], 0.0, 1e-15);
  mpm::Particles p;
  const auto stats = mpm::add_body(p, 2, body, materials::aluminium_seed000(), {cavity});
  const double removed = static_cast<double>(stats.lattice_points - stats.added) * 0.25e-12;
  EXPECT_NEAR(removed, std::numbers::pi * 25e-12, 0.03 * std::numbers::pi * 25e-12);
  EXPECT_THROW(mpm::cavity_at(2, body, 2e-6, 5e-6), InputError);
}

// A porous aluminium body (Δ ≈ 0.1) hits a rigid slip wall at 1000 m/s (seed §4.1 set-up) and a
// 3D single-cavity block runs (§4.2.2 set-up): smoke tests that the porous/3D paths run, keep
// every point on the grid and conserve mass.
TEST(SampleBuilders, PorousWallImpactAnd3DCavityRun) {
  const auto al = materials::aluminium_seed000();
  {
    const double h = 10e-6;
    const mpm::Body body{Vec3(0, 0, 0), Vec3(200e-6, 300e-6, 0), h / 2, Vec3(0, -1000.0, 0), 0};
    mpm::Particles p;
    mpm::add_body(p, 2, body, al, mpm::place_voids(2, body, {0.1, 15e-6, 0.0, 11}));
    const double m0 = mpm::totals(p).mass;
    mpm::SimulationOptions opt;
    opt.shape = mpm::ShapeKind::Gimp;
    mpm::Simulation sim(mpm::impact_grid(2, Vec3::Zero(), Vec3(200e-6, 320e-6, 0), h, mpm::Wall::Slip), {al},
                        std::move(p), opt);
    sim.run_until(20e-9);
    EXPECT_EQ(mpm::totals(sim.particles()).mass, m0);
    double tmax = 0;
    for (const auto& s : sim.particles().state) tmax = std::max(tmax, s.temperature);
    EXPECT_GT(tmax, 400.0);  // shocked and collapsing voids heat up
  }
  {
    const double h = 2e-6;
    const mpm::Body body{Vec3(-10e-6, -10e-6, 0), Vec3(10e-6, 10e-6, 30e-6), h / 2, Vec3(0, 0, 100.0), 0};
    mpm::Particles p;
    mpm::add_body(p, 3, body, al, {mpm::cavity_at(3, body, 10e-6, 4e-6)});
    mpm::Simulation sim(mpm::impact_grid(3, Vec3(-10e-6, -10e-6, 0), Vec3(10e-6, 10e-6, 40e-6), h, mpm::Wall::Stick),
                        {al}, std::move(p));
    for (int i = 0; i < 20; ++i) sim.step();
    EXPECT_GT(sim.time(), 0.0);
  }
}
