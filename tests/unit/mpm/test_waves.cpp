// Plane waves in 1D-like strips (2D plane strain, two cells wide, periodic in x): elastic wave,
// elastic-plastic two-wave structure, rigid-wall reflection. References are the uniaxial-strain
// wave solutions (e.g. Meyers, Dynamic Behavior of Materials, 1994, ch. 2 and 7).
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "shockfield/materials/library.hpp"
#include "strip.hpp"

using namespace shockfield;
namespace mpm = shockfield::mpm;

namespace {

// 6061-T6-like aluminium of the issue: E = 77.11 GPa, ν = 0.334, Y = 270 MPa, ρ = 2703 kg/m³.
// K = E/(3(1−2ν)) = 77.42 GPa, G = E/(2(1+ν)) = 28.90 GPa,
// c_L = √((K + 4G/3)/ρ) = 6549.7 m/s, c_p = √(K/ρ) = 5351.8 m/s (bulk wave, perfect plasticity),
// σ_HEL = (K + 4G/3)·Y/(2G) = Y(1−ν)/(1−2ν) = 541.6 MPa, u_HEL = σ_HEL/(ρc_L) = 30.59 m/s.
struct Al6061 {
  double rho = 2703.0, e = 77.11e9, nu = 0.334, y = 270e6;
  double k() const { return e / (3.0 * (1.0 - 2.0 * nu)); }
  double g() const { return e / (2.0 * (1.0 + nu)); }
  double cl() const { return std::sqrt((k() + 4.0 * g() / 3.0) / rho); }
  double cp() const { return std::sqrt(k() / rho); }
  double hel() const { return (k() + 4.0 * g() / 3.0) * y / (2.0 * g()); }
  // Linear artificial-viscosity coefficient 0.06 (LS-DYNA's FE default) rather than our 0.3: with
  // a linear bulk response these waves do not self-steepen, and the linear term, a viscosity
  // C_L·c·h, would spread them over ~15 cells and eat the HEL plateau between the two fronts.
  materials::SolidMaterial material(double yield) const {
    auto m = materials::elastic_plastic("al6061", rho, e, nu, yield);
    m.viscosity.linear = 0.06;
    return m;
  }
};

double front_speed(mpm::Simulation& sim, double h, double t1, double t2, double level) {
  sim.run_until(t1);
  const double y1 = strip::front_from_top(strip::profile(sim.particles(), h), level);
  sim.run_until(t2);
  const double y2 = strip::front_from_top(strip::profile(sim.particles(), h), level);
  return (y2 - y1) / (t2 - t1);
}

}  // namespace

TEST(Al6061, AnalyticReferenceValues) {
  const Al6061 a;
  EXPECT_NEAR(a.cl(), 6549.7, 0.5);
  EXPECT_NEAR(a.cp(), 5351.8, 0.5);
  EXPECT_NEAR(a.hel(), 541.6e6, 0.1e6);
}

// Elastic wave: a body at 20 m/s hits one at rest; each side carries u_p = 10 m/s and
// σ_yy = −ρc_L·u_p. Speed from the half-amplitude front at two times; tolerance 1% (issue).
// The stress is checked in the body that was at rest (its points move < 0.25 cell, so they cross
// no cell boundary) for every scheme, and in the moving body for GIMP only: with linear shape
// functions, points crossing cell boundaries give the known MPM cell-crossing noise (±20% stress
// ripple here, mean 4% low), which GIMP removes (Bardenhagen & Kober 2004).
class ElasticWave : public ::testing::TestWithParam<std::tuple<mpm::ShapeKind, mpm::UpdateScheme>> {};

TEST_P(ElasticWave, SpeedAndStress) {
  const Al6061 a;
  strip::Setup s;
  s.v_lower = 20.0;
  s.options.shape = std::get<0>(GetParam());
  s.options.scheme = std::get<1>(GetParam());
  auto sim = strip::make(s, a.material(1e12));
  const double len = s.cells * s.h;
  const double c = front_speed(sim, s.h, 0.3 * len / a.cl(), 0.7 * len / a.cl(), 5.0);
  EXPECT_NEAR(c, a.cl(), 0.01 * a.cl());
  const auto rows = strip::profile(sim.particles(), s.h);
  const double lower = std::get<0>(GetParam()) == mpm::ShapeKind::Gimp ? -0.3 * len : 0.0;
  const double syy = strip::mean(rows, lower, 0.3 * len, [](const strip::Row& r) { return r.syy; });
  EXPECT_NEAR(-syy, a.rho * a.cl() * 10.0, 0.01 * a.rho * a.cl() * 10.0);
  RecordProperty("wave_speed", std::to_string(c));
  RecordProperty("stress", std::to_string(syy));
}

INSTANTIATE_TEST_SUITE_P(Schemes, ElasticWave,
                         ::testing::Values(std::make_tuple(mpm::ShapeKind::Linear, mpm::UpdateScheme::MUSL),
                                           std::make_tuple(mpm::ShapeKind::Gimp, mpm::UpdateScheme::MUSL),
                                           std::make_tuple(mpm::ShapeKind::Linear, mpm::UpdateScheme::USL)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == mpm::ShapeKind::Gimp ? "Gimp" : "Linear") +
                                  (std::get<1>(info.param) == mpm::UpdateScheme::USL ? "USL" : "MUSL");
                         });

// Elastic-plastic bar: halves at 300 m/s and 0, u_p = 150 m/s. Elastic precursor at c_L carrying
// σ_HEL = 541.6 MPa, then the plastic wave at c_p to σ = σ_HEL + ρc_p(u_p − u_HEL) = 2.27 GPa.
// Tolerance 2% (issue): the fronts are smeared over a few cells by the artificial viscosity.
// GIMP, because the points cross cells (see ElasticWave). The plateau read 1 % low (2.247 GPa)
// with uniform GIMP, which lost the deviator behind the plastic front; with cpGIMP it reads
// 2.265 GPa (−0.2 %; DeviatorBehindShock.AluminiumBarPlateau holds it to 0.3 %).
TEST(ElasticPlasticBar, TwoWaveStructure) {
  const Al6061 a;
  strip::Setup s;
  s.cells = 300;
  s.v_lower = 300.0;
  s.options.shape = mpm::ShapeKind::Gimp;
  auto sim = strip::make(s, a.material(a.y));
  const double len = s.cells * s.h;
  const double t1 = 0.3 * len / a.cl(), t2 = 0.75 * len / a.cl();
  const double u_hel = a.hel() / (a.rho * a.cl());
  const double plastic_level = 0.5 * (u_hel + 150.0);

  sim.run_until(t1);
  auto rows = strip::profile(sim.particles(), s.h);
  const double e1 = strip::front_from_top(rows, 0.5 * u_hel), p1 = strip::front_from_top(rows, plastic_level);
  sim.run_until(t2);
  rows = strip::profile(sim.particles(), s.h);
  const double e2 = strip::front_from_top(rows, 0.5 * u_hel), p2 = strip::front_from_top(rows, plastic_level);
  const double ce = (e2 - e1) / (t2 - t1), cp = (p2 - p1) / (t2 - t1);
  EXPECT_NEAR(ce, 6549.7, 0.02 * 6549.7);
  EXPECT_NEAR(cp, 5351.8, 0.02 * 5351.8);

  // The precursor plateau: the part of [plastic front, elastic front] clear of both smeared fronts.
  const double hel = -strip::mean(rows, p2 + 0.4 * (e2 - p2), e2 - 0.15 * (e2 - p2), [](const strip::Row& r) { return r.syy; });
  EXPECT_NEAR(hel, 541.6e6, 0.02 * 541.6e6);
  const double plastic = -strip::mean(rows, 150.0 * t2 + 5 * s.h, 0.7 * p2, [](const strip::Row& r) { return r.syy; });
  const double plastic_ref = a.hel() + a.rho * a.cp() * (150.0 - u_hel);
  EXPECT_NEAR(plastic_ref, 2.27e9, 0.005e9);
  EXPECT_NEAR(plastic, plastic_ref, 0.02 * plastic_ref);
  RecordProperty("elastic_speed", std::to_string(ce));
  RecordProperty("plastic_speed", std::to_string(cp));
  RecordProperty("hel", std::to_string(hel));
  RecordProperty("plastic_stress", std::to_string(plastic));
}

// The 30 m/s case stays below the HEL: purely elastic, σ = ρc_L·15 m/s = 265.6 MPa (2%).
TEST(ElasticPlasticBar, BelowHelIsElastic) {
  const Al6061 a;
  strip::Setup s;
  s.v_lower = 30.0;
  s.options.shape = mpm::ShapeKind::Gimp;
  auto sim = strip::make(s, a.material(a.y));
  const double len = s.cells * s.h;
  sim.run_until(0.6 * len / a.cl());
  const auto rows = strip::profile(sim.particles(), s.h);
  const double syy = -strip::mean(rows, -0.3 * len, 0.3 * len, [](const strip::Row& r) { return r.syy; });
  EXPECT_NEAR(a.rho * a.cl() * 15.0, 265.6e6, 0.1e6);
  EXPECT_NEAR(syy, 265.6e6, 0.02 * 265.6e6);
  for (const auto& p : sim.particles().state) EXPECT_EQ(p.deviatoric.plastic_strain, 0.0);
}

// Rigid wall: a bar at −20 m/s onto a stick wall at y = 0 stops behind the reflected wave with
// σ_yy = −ρc_L·20 m/s (same state as the symmetric impact at ±20 m/s). Tolerance 1%.
TEST(RigidWall, ElasticBarStopsWithImpactStress) {
  const Al6061 a;
  const double h = 1e-3, len = 200 * h;
  const auto mat = a.material(1e12);
  for (mpm::Wall wall : {mpm::Wall::Stick, mpm::Wall::Slip}) {
    mpm::Particles p;
    mpm::add_body(p, 2, {Vec3(0, 0, 0), Vec3(2 * h, len, 0), h / 2, Vec3(0, -20.0, 0), 0}, mat);
    mpm::Simulation sim(mpm::impact_grid(2, Vec3::Zero(), Vec3(2 * h, len + 10 * h, 0), h, wall), {mat}, std::move(p));
    sim.run_until(0.6 * len / a.cl());
    const auto rows = strip::profile(sim.particles(), h);
    const double syy = -strip::mean(rows, 2 * h, 0.4 * len, [](const strip::Row& r) { return r.syy; });
    const double vy = strip::mean(rows, 2 * h, 0.4 * len, [](const strip::Row& r) { return r.vy; });
    EXPECT_NEAR(syy, a.rho * a.cl() * 20.0, 0.01 * a.rho * a.cl() * 20.0);
    EXPECT_NEAR(vy, 0.0, 0.2);
  }
}
