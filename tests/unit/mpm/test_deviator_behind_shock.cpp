// The deviatoric stress behind shocks (docs/theory/mpm.md, "Deviatoric stress behind shocks"):
// elastic–perfectly-plastic bars against the two-wave solution (plastic_bar.hpp) and the library
// copper in symmetric impact against Rankine–Hugoniot, with the deviator at yield behind the
// shock. Each check also runs the pre-fix transfer (uniform GIMP, no initial projection) where
// that shows what the fix removed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plastic_bar.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

mpm::SimulationOptions before_fix() {
  mpm::SimulationOptions o;
  o.shape = mpm::ShapeKind::UniformGimp;
  o.project_initial_velocity = false;
  return o;
}

void record(const std::string& key, double value) { ::testing::Test::RecordProperty(key, std::to_string(value)); }

}  // namespace

// Copper-like bar at 400 m/s (u_p = 200 m/s), 2 mm per body at 20, 10 and 5 µm cells (100, 200,
// 400 cells; about a second in all). The plastic plateau −σ_yy is within 0.3 % of the two-wave
// value at every resolution (issue 16; measured −0.07 / −0.04 / −0.02 % with the default
// C_L = 1, against −0.48 / −0.35 / −0.79 % before the fix) and does not get worse as the grid is
// refined. The deviator s_yy is measured against −(2/3)Y over the window from five cells above
// the impact face to 0.7 of the plastic front: measured 0.92 / 0.88 / 0.91 of yield on average
// (0.29 / 0.28 / 0.18 before) and at least 0.82 in each fifth of the window. It is not yet at
// −(2/3)Y everywhere: the impact face of a bar that moves through the grid keeps radiating
// (docs/theory/mpm.md); the bounds below (0.85 mean, 0.75 per fifth) hold today's level.
TEST(DeviatorBehindShock, CopperLikeBarPlateauAtEveryResolution) {
  const auto cu = plastic_bar::copper();
  EXPECT_NEAR(cu.plateau(200.0), 6.9407e9, 0.0005e9);  // σ_HEL = 247.5 MPa, u_HEL = 5.9 m/s, ρc_b = 3.448e7 kg/(m² s)
  double previous = 1.0;
  for (double h : {20e-6, 10e-6, 5e-6}) {
    const int cells = static_cast<int>(std::lround(2e-3 / h));
    const auto r = plastic_bar::run(cu, 400.0, h, cells, materials::ArtificialViscosity{}.linear);
    const double error = std::abs(r.plateau / r.reference - 1.0);
    EXPECT_LT(error, 0.003) << "h = " << h;
    EXPECT_LE(error, previous + 0.0005) << "h = " << h;  // not worse when refined (0.05 % of slack)
    previous = error;
    EXPECT_GT(r.deviator, 0.85) << "h = " << h;
    EXPECT_LT(r.deviator, 1.01) << "h = " << h;
    EXPECT_GT(r.deviator_min, 0.75) << "h = " << h;
    record("plateau_error_h" + std::to_string(static_cast<int>(h * 1e6)), r.plateau / r.reference - 1.0);
    record("deviator_h" + std::to_string(static_cast<int>(h * 1e6)), r.deviator);
  }
}

// The same bar with the strength-preserving options (XPIC(2) velocity update and the dilatation
// smoothed over the stencil; docs/theory/mpm.md, "Deviatoric stress behind shocks", cause 4): s_yy
// stays at −(2/3)Y from five cells above the impact face to 0.7 of the plastic front. Measured
// with the B-bar force of the smoothing (test_smoothed_dilatation.cpp): mean 0.994 / 0.993 / 0.993,
// every fifth of the window ≥ 0.973 / 0.980 / 0.982 at 20 / 10 / 5 µm, plateau −0.026 / +0.017 /
// +0.007 % of the two-wave value (with the former, non-conjugate force 0.996 / 0.993 / 0.993,
// fifths ≥ 0.982, plateau −0.047 / +0.014 / +0.007 %). Bounds: mean > 0.98 and each fifth > 0.97
// (the stripes the plain defaults leave read 0.82–0.86 per fifth; a perfectly plastic point
// cannot exceed 1 beyond round-off), plateau within 0.3 % (issue 16), not worse when refined.
// Each ingredient alone falls short at 10 µm (XPIC(2) alone 0.898, smoothing alone with a fifth
// at 0.68, 0.69 with the B-bar force): the last two checks fail if either one stops being needed.
TEST(DeviatorBehindShock, StrengthPreservingTransferKeepsYieldAtEveryResolution) {
  const auto cu = plastic_bar::copper();
  const double c_l = materials::ArtificialViscosity{}.linear;
  double previous = 1.0;
  for (double h : {20e-6, 10e-6, 5e-6}) {
    const int cells = static_cast<int>(std::lround(2e-3 / h));
    const auto r = plastic_bar::run(cu, 400.0, h, cells, c_l, plastic_bar::strength_preserving());
    const double error = std::abs(r.plateau / r.reference - 1.0);
    EXPECT_LT(error, 0.003) << "h = " << h;
    EXPECT_LE(error, previous + 0.0002) << "h = " << h;
    previous = error;
    EXPECT_GT(r.deviator, 0.98) << "h = " << h;
    EXPECT_LT(r.deviator, 1.0 + 1e-9) << "h = " << h;
    EXPECT_GT(r.deviator_min, 0.97) << "h = " << h;
    const std::string k = std::to_string(static_cast<int>(h * 1e6));
    record("plateau_error_h" + k, r.plateau / r.reference - 1.0);
    record("deviator_h" + k, r.deviator);
    record("deviator_min_h" + k, r.deviator_min);
  }
  auto xpic_only = plastic_bar::strength_preserving();
  xpic_only.smooth_dilatation = false;
  auto smoothing_only = plastic_bar::strength_preserving();
  smoothing_only.xpic_order = 0;
  EXPECT_LT(plastic_bar::run(cu, 400.0, 10e-6, 200, c_l, xpic_only).deviator, 0.95);
  EXPECT_LT(plastic_bar::run(cu, 400.0, 10e-6, 200, c_l, smoothing_only).deviator_min, 0.9);
}

// The same bar with the transfer of before the fix (uniform GIMP boxes, FLIP from the first step)
// loses the deviator: s_yy at 0.38 of yield at 10 µm with today's C_L = 1 (0.29 / 0.28 / 0.18 at
// 20 / 10 / 5 µm with the former C_L = 0.3, the plateau 0.35–0.8 % low). This test documents the
// cause and fails if the shocked state stops depending on it.
TEST(DeviatorBehindShock, UniformGimpLosesTheDeviator) {
  const auto cu = plastic_bar::copper();
  const auto r = plastic_bar::run(cu, 400.0, 10e-6, 200, materials::ArtificialViscosity{}.linear, before_fix());
  EXPECT_LT(r.deviator, 0.6);
  record("deviator", r.deviator);
}

// The aluminium of ElasticPlasticBar.TwoWaveStructure (300 m/s, u_p = 150 m/s, 2.27 GPa), 300 cells:
// with the default C_L the plateau is within 0.3 % and s_yy at yield within 5 %. With the C_L = 0.06
// TwoWaveStructure needs (its HEL plateau) the plateau was 1 % low before the fix and is within
// 0.3 % now, with s_yy at 0.89 of yield (the ringing C_L = 0.06 leaves; see the slow study).
TEST(DeviatorBehindShock, AluminiumBarPlateau) {
  const auto al = plastic_bar::aluminium();
  EXPECT_NEAR(al.plateau(150.0), 2.269e9, 0.002e9);
  for (double c_l : {materials::ArtificialViscosity{}.linear, 0.06}) {
    const auto r = plastic_bar::run(al, 300.0, 1e-3, 300, c_l);
    EXPECT_NEAR(r.plateau, r.reference, 0.003 * r.reference) << c_l;
    EXPECT_GT(r.deviator, c_l > 0.5 ? 0.95 : 0.85) << c_l;
    record("plateau_error_CL" + std::to_string(c_l), r.plateau / r.reference - 1.0);
    record("deviator_CL" + std::to_string(c_l), r.deviator);
  }
}

// Library copper (Mie-Grüneisen c0 = 3940 m/s, λ = 1.489; G = 47.7 GPa, σ_Y = 120 MPa + 470 MPa·ε̄p)
// at ±500 and ±1000 m/s, 200 cells of 10 µm per body: behind the shock the von Mises stress is
// the current yield stress σ_Y(ε̄p) within 5 % (issue 16; measured 0.98 / 1.00 with the default
// C_L = 1, 0.23 / 0.26 with the former C_L = 0.3), and Us, −σ_yy and ρ are within 2 % of
// Rankine–Hugoniot: Us = c0 + λu_p, −σ_yy = ρ0·Us·u_p, ρ = ρ0·Us/(Us − u_p) with the measured Us
// for the last two (the strength adds (2/3)σ_Y ≈ 0.1 GPa to σ_yy, 0.2–0.5 %, inside the bound).
TEST(DeviatorBehindShock, CopperSymmetricImpactKeepsVonMisesAtYield) {
  const auto cu = materials::copper();
  for (double v : {500.0, 1000.0}) {
    strip::Setup s;
    s.cells = 200;
    s.h = 10e-6;
    s.v_lower = v;
    s.v_upper = -v;
    s.options.shape = mpm::ShapeKind::Gimp;
    auto sim = strip::make(s, cu);
    const double len = s.cells * s.h, us_ref = cu.eos.c0 + cu.eos.lambda * v;
    const double t1 = 0.3 * len / us_ref, t2 = 0.6 * len / us_ref;
    sim.run_until(t1);
    const double y1 = strip::front_from_top(strip::profile(sim.particles(), s.h), -0.5 * v);
    sim.run_until(t2);
    const auto rows = strip::profile(sim.particles(), s.h);
    const double y2 = strip::front_from_top(rows, -0.5 * v);
    const double us = (y2 - y1) / (t2 - t1) + v;  // lab front speed + the upstream material speed
    auto avg = [&](auto f) { return strip::mean(rows, 5 * s.h, 0.7 * y2, f); };
    const double sigma = -avg([](const strip::Row& r) { return r.syy; });
    const double rho = avg([](const strip::Row& r) { return r.rho; });
    const double vm = avg([](const strip::Row& r) { return r.vm; });
    const double yield = cu.strength.yield_stress(avg([](const strip::Row& r) { return r.eqp; }));  // linear in ε̄p
    EXPECT_NEAR(us, us_ref, 0.02 * us_ref) << v;
    EXPECT_NEAR(sigma, cu.eos.rho0 * us * v, 0.02 * cu.eos.rho0 * us * v) << v;
    EXPECT_NEAR(rho, cu.eos.rho0 * us / (us - v), 0.02 * cu.eos.rho0 * us / (us - v)) << v;
    EXPECT_NEAR(vm / yield, 1.0, 0.05) << v;
    const std::string k = std::to_string(static_cast<int>(v));
    record("Us_" + k, us);
    record("sigma_" + k, sigma);
    record("vm_over_yield_" + k, vm / yield);
  }
}
