// Porous bodies with periodic lateral sides (Xu et al. 2015, §4.1: a periodic porous sample): voids cross
// the periodic sides as wrapped images, so the void fraction is the same next to a side as in the
// interior, no void overlaps another's periodic image, and the porosity counts each void once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/sample_builders.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

constexpr double kL = 400e-6, kR = 10e-6;  // period and void radius
const mpm::Body kBody{Vec3(0, 0, 0), Vec3(kL, kL, 0), 1e-6, Vec3::Zero(), 0};
const mpm::PeriodicAxes kPeriodicX{true, false, false};

// Area of the disc (centre cx, radius r) with x < a: r²(π − acos u + u√(1 − u²)), u = (a − cx)/r.
double disc_area_left_of(double a, double cx, double r) {
  const double u = std::clamp((a - cx) / r, -1.0, 1.0);
  return r * r * (std::numbers::pi - std::acos(u) + u * std::sqrt(1.0 - u * u));
}

// Exact void area fraction of the strip x0 <= x < x1 of the body (voids lie inside in y).
double strip_void_fraction(const std::vector<mpm::Void>& voids, double x0, double x1) {
  double area = 0.0;
  for (const auto& v : voids)
    area += disc_area_left_of(x1, v.centre[0], v.radius) - disc_area_left_of(x0, v.centre[0], v.radius);
  return area / ((x1 - x0) * kL);
}

struct StripBias {
  double mean = 0.0, standard_error = 0.0;
};

// Over seeds: (void fraction in the two side strips of width r) − (fraction in the middle half).
StripBias side_strip_bias(bool cross_sides) {
  std::vector<double> d;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    mpm::VoidSpec spec{0.2, kR, 0.0, seed};
    spec.cross_periodic_sides = cross_sides;
    const auto voids = mpm::place_voids(2, kBody, spec, kPeriodicX);
    const double sides = 0.5 * (strip_void_fraction(voids, 0.0, kR) + strip_void_fraction(voids, kL - kR, kL));
    d.push_back(sides - strip_void_fraction(voids, 0.25 * kL, 0.75 * kL));
  }
  StripBias b;
  for (double x : d) b.mean += x / static_cast<double>(d.size());
  double var = 0.0;
  for (double x : d) var += (x - b.mean) * (x - b.mean) / static_cast<double>(d.size() - 1);
  b.standard_error = std::sqrt(var / static_cast<double>(d.size()));
  return b;
}

}  // namespace

// With periodic sides the side strips hold as much void as the interior (within 3 standard errors
// over 60 seeds); with the sides treated as faces (voids wholly inside) they hold clearly less,
// which is the bias the wrapping removes and shows that the comparison can see it.
TEST(PeriodicVoids, SideStripsHoldTheInteriorVoidFraction) {
  const StripBias wrapped = side_strip_bias(true);
  EXPECT_LT(std::abs(wrapped.mean), 3.0 * wrapped.standard_error) << wrapped.mean;
  EXPECT_LT(wrapped.standard_error, 0.01);
  const StripBias inside = side_strip_bias(false);
  EXPECT_LT(inside.mean, -5.0 * inside.standard_error) << inside.mean;
  EXPECT_LT(inside.mean, -0.05);
}

// Placed voids have their centres in the period; no pair overlaps under the minimum image (the
// distance over ±1 period), each listed image is a placed void shifted by one period and reaches
// into the body, and the lattice porosity (images cutting the points near the sides) equals the
// placed void area, which is the target within one void.
TEST(PeriodicVoids, NoOverlapWithImagesAndExactPorosity) {
  const mpm::VoidSpec spec{0.3, kR, 0.3, 5};
  const auto voids = mpm::place_voids(2, kBody, spec, kPeriodicX);
  std::vector<mpm::Void> placed, images;
  for (const auto& v : voids) (v.centre[0] >= 0.0 && v.centre[0] < kL ? placed : images).push_back(v);
  ASSERT_FALSE(images.empty());
  for (std::size_t k = 0; k < voids.size(); ++k)  // the placed voids first, then the images
    EXPECT_EQ(k < placed.size(), voids[k].centre[0] >= 0.0 && voids[k].centre[0] < kL) << k;
  double area = 0.0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& a = placed[i];
    area += std::numbers::pi * a.radius * a.radius;
    EXPECT_GE(a.centre[1] - a.radius, 0.0);
    EXPECT_LE(a.centre[1] + a.radius, kL);
    for (std::size_t j = 0; j <= i; ++j)
      for (double shift : {-kL, 0.0, kL}) {
        if (i == j && shift == 0.0) continue;
        const Vec3 d = a.centre - placed[j].centre - Vec3(shift, 0, 0);
        EXPECT_GE(d.norm(), a.radius + placed[j].radius) << i << " " << j << " " << shift;
      }
  }
  for (const auto& im : images) {
    EXPECT_TRUE(im.centre[0] - im.radius < 0.0 || im.centre[0] + im.radius > kL);
    int sources = 0;
    for (const auto& p : placed)
      sources += p.radius == im.radius && p.centre[1] == im.centre[1] && std::abs(std::abs(p.centre[0] - im.centre[0]) - kL) < 1e-12;
    EXPECT_EQ(sources, 1);
  }
  const double body_area = kL * kL, one_void = std::numbers::pi * kR * kR * 1.3 * 1.3;
  EXPECT_NEAR(area, spec.porosity * body_area, one_void);
  mpm::Particles p;
  const auto stats = mpm::add_body(p, 2, kBody, materials::aluminium_seed000(), voids);
  EXPECT_NEAR(stats.porosity(), area / body_area, 2e-3);
}

// 3D, periodic along x and y: no overlap under the minimum image and the lattice porosity counts
// the voids crossing the sides (and edges) once.
TEST(PeriodicVoids, ThreeDimensionalBodyWrapsBothLateralAxes) {
  const double l = 60e-6, r = 6e-6;
  const mpm::Body body{Vec3(0, 0, 0), Vec3(l, l, l), 1e-6, Vec3::Zero(), 0};
  const auto voids = mpm::place_voids(3, body, {0.15, r, 0.0, 9}, {true, true, false});
  double volume = 0.0;
  std::size_t placed = 0;
  for (const auto& v : voids)
    if (v.centre[0] >= 0 && v.centre[0] < l && v.centre[1] >= 0 && v.centre[1] < l) {
      ++placed;
      volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    }
  EXPECT_GT(voids.size(), placed);  // some cross a side
  for (std::size_t i = 0; i < voids.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GE((voids[i].centre - voids[j].centre).norm(), 2.0 * r - 1e-12);  // images included
  mpm::Particles p;
  const auto stats = mpm::add_body(p, 3, body, materials::aluminium_seed000(), voids);
  EXPECT_NEAR(stats.porosity(), volume / (l * l * l), 3e-3);
}

TEST(PeriodicVoids, ImpossiblePackingIsStillAnInputError) {
  try {
    mpm::place_voids(2, mpm::Body{Vec3(0, 0, 0), Vec3(1e-3, 1e-3, 0), 5e-6, Vec3::Zero(), 0}, {0.54, 50e-6, 0.0, 1},
                     kPeriodicX);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("could place only"), std::string::npos) << e.what();
  }
}
