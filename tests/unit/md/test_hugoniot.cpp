// Shock-front tracking and Hugoniot extraction on synthetic profiles with a known answer: a
// steady square wave moving at U_s behind which material moves at U_p with density
// ρ₀U_s/(U_s − U_p) (mass conservation), in front of a piston moving at U_p.
#include <gtest/gtest.h>

#include "shockfield/md/diagnostics/hugoniot.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

std::vector<Profile> square_wave(double us, double up, double rho0, double width, double length) {
  std::vector<Profile> frames;
  for (int k = 0; k <= 20; ++k) {
    Profile p;
    p.time = 0.5 * k;
    const double front = us * p.time, wall = up * p.time;
    for (double x = 0.5 * width; x < length; x += width) {
      ProfileBin b;
      b.position = x;
      b.count = x > wall ? 100 : 0;
      const bool shocked = x < front;
      // Linear ramp across the bin the front is in, so the front is located to sub-bin accuracy.
      const double frac = std::clamp((front - (x - 0.5 * width)) / width, 0.0, 1.0);
      b.velocity = Vec3(0, 0, up * frac);
      b.density = shocked ? rho0 * us / (us - up) : rho0;
      b.temperature = shocked ? 900.0 : 300.0;
      b.pressure[2] = shocked ? 0.1 * rho0 * us * up * 10.0 : 0.0;
      p.bins.push_back(b);
    }
    frames.push_back(p);
  }
  return frames;
}

}  // namespace

TEST(Hugoniot, RecoversTheStateOfASteadySquareWave) {
  const double us = 50.0, up = 15.0, rho0 = 8.9;  // Å/ps (5 and 1.5 km/s), g/cm³
  const auto frames = square_wave(us, up, rho0, 2.0, 700.0);
  const HugoniotState h = extract_hugoniot(frames, 2, +1, up, 0.0, 0.0);
  EXPECT_NEAR(h.us, 5.0, 0.02);
  EXPECT_NEAR(h.up, 1.5, 1e-9);
  EXPECT_NEAR(h.density, rho0 * us / (us - up), 1e-9);
  EXPECT_NEAR(h.density0, rho0, 1e-12);
  EXPECT_NEAR(h.pressure_rh, rho0 * 5.0 * 1.5, 0.5);
  EXPECT_NEAR(h.temperature, 900.0, 1e-9);
  EXPECT_TRUE(h.note.empty()) << h.note;
}

TEST(Hugoniot, SaysWhyWhenThereIsNoShock) {
  std::vector<Profile> frames(5);
  for (int k = 0; k < 5; ++k) {
    frames[k].time = k;
    frames[k].bins.resize(10);
    for (int b = 0; b < 10; ++b) {
      frames[k].bins[b].position = b;
      frames[k].bins[b].count = 10;
    }
  }
  const HugoniotState h = extract_hugoniot(frames, 2, +1, 10.0, 0.0, 0.0);
  EXPECT_TRUE(std::isnan(h.us));
  EXPECT_FALSE(h.note.empty());
}

// Regression (issue 14): a front that runs into the free end left hugoniot_<stage>.toml with
// `nan` values (no bins ahead of it) and no reason; `shockfield hugoniot` then failed reading it.
TEST(Hugoniot, SaysTheFrontReachedTheFreeEndAndWritesNoNan) {
  const double us = 50.0, up = 15.0, rho0 = 8.9;
  // 170 Å: the front (50 Å/ps) reaches the free end at t = 3.4 ps, just after the fit window
  // (t >= 3 ps of 0..10 ps) opens, so fewer than 3 profiles of the window see a steady shock.
  const HugoniotState h = extract_hugoniot(square_wave(us, up, rho0, 2.0, 170.0), 2, +1, up, 0.0, 0.0);
  EXPECT_FALSE(h.complete());
  EXPECT_NE(h.note.find("reached the free end"), std::string::npos) << h.note;
  EXPECT_NE(h.note.find("make the sample longer or the stage shorter"), std::string::npos) << h.note;
  const std::string toml = hugoniot_toml(h);
  EXPECT_EQ(toml.find("nan"), std::string::npos) << toml;
  EXPECT_NE(toml.find("complete = false"), std::string::npos) << toml;
}

TEST(Hugoniot, FitStopsWhereTheFrontReachesTheFreeEnd) {
  // 400 Å: the end is reached at t = 8 ps; the window's profiles before it give the exact state.
  const double us = 50.0, up = 15.0, rho0 = 8.9;
  const HugoniotState h = extract_hugoniot(square_wave(us, up, rho0, 2.0, 400.0), 2, +1, up, 0.0, 0.0);
  EXPECT_TRUE(h.complete()) << h.note;
  EXPECT_NEAR(h.us, 5.0, 0.02);
  EXPECT_NEAR(h.density0, rho0, 1e-12);
  EXPECT_NE(h.note.find("reached the free end"), std::string::npos) << h.note;
  EXPECT_NE(hugoniot_toml(h).find("complete = true"), std::string::npos);
}
