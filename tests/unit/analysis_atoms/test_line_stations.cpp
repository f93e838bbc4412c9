// Stations along a cluster's line (line_stations.hpp): on a ring of "core atoms" (a curved loop)
// each station's tangent is the ring's tangent and its centre on the ring, the stations are one
// spacing apart; on a straight tube across the periodic box every station is along the tube and
// stations_are_straight() says so, while it says no for the ring. A sheet has no line direction.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/line_stations.hpp"
#include "shockfield/core/error.hpp"

using namespace shockfield;
using namespace shockfield::analysis::atoms;

namespace {

AtomFrame periodic_frame(double length) {
  AtomFrame f;
  for (int d = 0; d < 3; ++d) {
    f.box.lo[d] = 0;
    f.box.hi[d] = length;
    f.box.boundary[d] = geometry::Boundary::periodic;
  }
  return f;
}

// Points filling a tube of radius `tube` about a circle of radius R in the plane z = z0 centred
// at `centre` (crossing the periodic faces when the centre is near a corner), wrapped into the box.
std::vector<std::size_t> add_ring(AtomFrame& f, const Vec3& centre, double R, double tube) {
  std::vector<std::size_t> members;
  const int around = 160, across = 6;
  for (int i = 0; i < around; ++i) {
    const double phi = 2 * std::numbers::pi * i / around;
    const Vec3 radial(std::cos(phi), std::sin(phi), 0);
    for (int j = 0; j < across; ++j) {
      const double psi = 2 * std::numbers::pi * (j + 0.5 * (i % 2)) / across;
      Vec3 x = centre + (R + tube * std::cos(psi)) * radial + tube * std::sin(psi) * Vec3::UnitZ();
      for (int d = 0; d < 3; ++d) x[d] -= f.box.hi[d] * std::floor(x[d] / f.box.hi[d]);
      members.push_back(f.positions.size());
      f.positions.push_back(x);
    }
  }
  return members;
}

}  // namespace

TEST(LineStations, FollowACurvedLoopAcrossPeriodicFaces) {
  AtomFrame f = periodic_frame(60.0);
  const Vec3 centre(55.0, 3.0, 58.0);  // the ring crosses all three pairs of faces
  const double R = 20.0, spacing = 7.2;
  const auto members = add_ring(f, centre, R, 1.2);
  const auto stations = line_stations(f, members, spacing);
  // Every atom lies within one spacing of a station and the stations are at least one spacing
  // apart, so neighbouring stations are s to 2s apart along the ring: πR/s to 2πR/s of them.
  const double most = 2 * std::numbers::pi * R / spacing;
  EXPECT_GE(stations.size(), static_cast<std::size_t>(std::floor(most / 2)));
  EXPECT_LE(stations.size(), static_cast<std::size_t>(std::ceil(most)));
  for (const LineStation& s : stations) {
    const Vec3 d = f.box.minimum_image(s.centre - centre);
    const Vec3 radial = Vec3(d.x(), d.y(), 0).normalized();
    // A chord of the ring within ±s: its mean lies inside by R(1 − sin θ/θ), θ = s/R: 0.38 Å here.
    EXPECT_NEAR(Vec3(d.x(), d.y(), 0).norm(), R, 0.6);
    EXPECT_NEAR(d.z(), 0.0, 0.1);  // the tube's cross-section is sampled by 6 points only
    EXPECT_LT(std::abs(s.tangent.dot(radial)), 0.05);       // along the ring, not across it
    EXPECT_LT(std::abs(s.tangent.z()), 0.02);
    EXPECT_NEAR(s.half_width, std::sqrt(5.0 / 2.0) * 1.2, 0.25);  // tube of circle radius r: λ = r²/2 across it
  }
  EXPECT_FALSE(stations_are_straight(stations, f.box, centre, Vec3::UnitX(), 5.0));
  // Oriented about the loop's normal, the tangents all turn the same way: counter-clockwise about
  // +z, clockwise about −z.
  auto oriented = stations;
  orient_circulation(oriented, f.box, centre, Vec3::UnitZ());
  for (const LineStation& s : oriented)
    EXPECT_GT(f.box.minimum_image(s.centre - centre).cross(s.tangent).z(), 0.9 * R);
  orient_circulation(oriented, f.box, centre, -Vec3::UnitZ());
  int counter_clockwise = 0;
  for (const LineStation& s : oriented) counter_clockwise += f.box.minimum_image(s.centre - centre).cross(s.tangent).z() > 0;
  EXPECT_EQ(counter_clockwise, 0);
}

TEST(LineStations, AStraightTubeIsStraight) {
  AtomFrame f = periodic_frame(40.0);
  std::vector<std::size_t> members;
  for (int i = 0; i < 80; ++i)  // along y through the whole periodic box, at x = 38.5 (wraps in x too)
    for (int j = 0; j < 4; ++j) {
      const double psi = std::numbers::pi / 2 * j;
      Vec3 x(38.5 + 1.5 * std::cos(psi), 0.5 * i, 20.0 + 1.5 * std::sin(psi));
      x.x() -= 40.0 * std::floor(x.x() / 40.0);
      members.push_back(f.positions.size());
      f.positions.push_back(x);
    }
  const auto stations = line_stations(f, members, 7.0);
  ASSERT_GE(stations.size(), 4u);
  for (const LineStation& s : stations) EXPECT_GT(std::abs(s.tangent.y()), 0.999);
  EXPECT_TRUE(stations_are_straight(stations, f.box, Vec3(38.5, 20.0, 20.0), Vec3::UnitY(), 1.0));
  EXPECT_FALSE(stations_are_straight(stations, f.box, Vec3(34.0, 20.0, 20.0), Vec3::UnitY(), 1.0));  // 4.5 Å off
}

// A sheet across the whole periodic plane (a stacking fault spanning the box) has no edge, so no
// station has a line direction. (At a sheet's edge a half-disc of atoms has semi-axes in the ratio
// 1.9 and does get one, along the edge: where a fault's bounding partial is.)
TEST(LineStations, ASheetHasNoLineDirection) {
  AtomFrame f = periodic_frame(50.0);
  std::vector<std::size_t> members;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) {
      members.push_back(f.positions.size());
      f.positions.push_back(Vec3(1.0 * i, 1.0 * j, 25.0));
    }
  EXPECT_TRUE(line_stations(f, members, 6.0).empty());
  EXPECT_THROW(line_stations(f, members, 0.0), InputError);
}
