// The cavity tracker on prescribed, exactly known deformations of a body with one cavity: an
// area-preserving expansion of the cavity (the §4.2.2 tensile growth, where the hoop stretch
// around the cavity far exceeds J^(1/d)) and a rigid rotation. Both keep the material's area, so
// the cavity's area is known in closed form at every stage.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/cavity_tracker.hpp"
#include "shockfield/mpm/sample_builders.hpp"

namespace {

using namespace shockfield;

constexpr double kSpacing = 1e-6, kRadius0 = 10e-6;

struct Block {
  mpm::Void cavity;
  mpm::Particles reference;
};

Block block_with_cavity() {
  const mpm::Body body{Vec3(0, 0, 0), Vec3(140e-6, 140e-6, 0), kSpacing, Vec3::Zero(), 0};
  Block b{mpm::cavity_at(2, body, 70e-6, kRadius0), {}};
  mpm::add_body(b.reference, 2, body, materials::aluminium_seed000(), {b.cavity});
  return b;
}

// Incompressible growth of a cylindrical cavity from radius a0 to a: a point at distance R from
// the centre moves to r = √(R² + a² − a0²) along its ray, so F = (R/r) e_r⊗e_r + (r/R) e_θ⊗e_θ
// (det F = 1: no density change, yet a hoop stretch r/R of up to a/a0 at the cavity's rim).
mpm::Particles grown(const Block& b, double a) {
  mpm::Particles p = b.reference;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 d = p.x[i] - b.cavity.centre;
    const double big_r = d.norm(), r = std::sqrt(big_r * big_r + a * a - kRadius0 * kRadius0);
    const Vec3 er = d / big_r, et(-er[1], er[0], 0.0);
    p.x[i] = b.cavity.centre + r * er;
    p.state[i].deformation = (big_r / r) * er * er.transpose() + (r / big_r) * et * et.transpose();
    p.state[i].deformation(2, 2) = 1.0;
  }
  return p;
}

// The cavity grows to 2.5 times its radius (6.25 times its area) in steps of 5 % of a0, the way
// a run measures it every series interval; the tracker must follow it all the way. Reference: the
// area measured on the undeformed block (the lattice's discrete disc) plus π(a² − a0²).
TEST(MpmCavityTracker, FollowsAnIncompressiblyGrowingCavity) {
  const Block b = block_with_cavity();
  mpm::CavityTracker tracker(2, b.cavity, kSpacing);
  const double a_first = tracker.measure(b.reference, 0.0).size;
  EXPECT_NEAR(a_first, std::numbers::pi * kRadius0 * kRadius0,
              0.04 * std::numbers::pi * kRadius0 * kRadius0);
  for (int k = 1; k <= 30; ++k) {
    const double a = kRadius0 * (1.0 + 0.05 * k);
    const mpm::CavityMeasure m = tracker.measure(grown(b, a), 1e-9 * k);
    const double expected = a_first + std::numbers::pi * (a * a - kRadius0 * kRadius0);
    // 2 %: one raster cell (half the spacing) of the rim is 2·(0.5 µm)/a of the area
    EXPECT_NEAR(m.size, expected, 0.02 * expected) << "a = " << a;
    EXPECT_NEAR(m.collapsibility, 1.0 - m.size / a_first, 1e-12);
    EXPECT_NEAR(m.horizontal, 2 * a, 2 * kSpacing) << "a = " << a;
    EXPECT_NEAR(m.vertical, 2 * a, 2 * kSpacing) << "a = " << a;
  }
}

// A rigid rotation by 30° about the cavity centre: the particle domains become rotated squares,
// which axis-aligned boxes of the same size do not tile. Area and sizes must not change.
TEST(MpmCavityTracker, RigidRotationKeepsTheArea) {
  const Block b = block_with_cavity();
  mpm::CavityTracker tracker(2, b.cavity, kSpacing);
  const double a_first = tracker.measure(b.reference, 0.0).size;
  const double angle = std::numbers::pi / 6.0;
  Mat3 rot = Mat3::Identity();
  rot.topLeftCorner(2, 2) << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  mpm::Particles p = b.reference;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x[i] = b.cavity.centre + rot * (p.x[i] - b.cavity.centre);
    p.state[i].deformation = rot;
  }
  const mpm::CavityMeasure m = tracker.measure(p, 1e-9);
  EXPECT_NEAR(m.size, a_first, 0.02 * a_first);
  EXPECT_NEAR(m.horizontal, 2 * kRadius0, 2 * kSpacing);
}

}  // namespace
