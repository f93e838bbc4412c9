// J2 radial return (Xu et al. 2015, eqs. 3-4), the combined point update, and the material library.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/materials/strength/j2_plasticity.hpp"

using namespace shockfield;
using namespace shockfield::materials;

namespace {
// Isochoric uniaxial tension: de = dε·diag(1, −½, −½), so σ_eq = 3G·ε while elastic.
Mat3 tension(double de) { return de * Eigen::Vector3d(1.0, -0.5, -0.5).asDiagonal(); }
}  // namespace

// Analytic uniaxial case: elastic to ε_y = σ_Y0/(3G), then dσ_eq/dε = 3G·H/(3G + H). Radial return
// is exact on a proportional path, so one large increment and 1000 small ones both match to round-off.
TEST(J2Plasticity, UniaxialTensionWithLinearHardening) {
  const J2Plasticity j2 = J2Plasticity::from_young(69e9, 0.33, 120e6, 384e6);
  const double g = j2.shear_modulus, h = j2.tangent_modulus;
  const double eps = 0.02, eps_y = 120e6 / (3.0 * g);
  const double expected = 120e6 + 3.0 * g * h / (3.0 * g + h) * (eps - eps_y);
  J2Plasticity::State one, many;
  j2.update(one, tension(eps));
  for (int i = 0; i < 1000; ++i) j2.update(many, tension(eps / 1000));
  EXPECT_NEAR(von_mises(one.s), expected, 1e-6 * expected);
  EXPECT_NEAR(von_mises(many.s), expected, 1e-6 * expected);
  // Hardening (eq. 4): the current yield stress equals σ_Y0 + E_tan·ε̄p.
  EXPECT_NEAR(von_mises(many.s), j2.yield_stress(many.plastic_strain), 1e-6 * expected);
  EXPECT_NEAR(many.plastic_strain, (eps - eps_y) * 3.0 * g / (3.0 * g + h), 1e-9);
  EXPECT_NEAR(many.s.trace(), 0.0, 1e-3);
}

TEST(J2Plasticity, ElasticBelowYield) {
  const J2Plasticity j2 = J2Plasticity::from_young(69e9, 0.33, 120e6, 384e6);
  J2Plasticity::State st;
  const auto inc = j2.update(st, tension(0.5 * 120e6 / (3.0 * j2.shear_modulus)));
  EXPECT_EQ(inc.equivalent, 0.0);
  EXPECT_NEAR(von_mises(st.s), 60e6, 1.0);
}

// Plastic work Σ s:Δe^p = ∫σ_Y dε̄p = σ_Y0·ε̄p + ½E_tan·ε̄p² (to the O(Δε) of the end-point rule).
TEST(J2Plasticity, PlasticWork) {
  const J2Plasticity j2 = J2Plasticity::from_young(69e9, 0.33, 120e6, 3.84e9);
  J2Plasticity::State st;
  double w = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const auto inc = j2.update(st, tension(0.1 / 4000));
    w += st.s.cwiseProduct(inc.plastic).sum();
  }
  const double ep = st.plastic_strain;
  EXPECT_NEAR(w, 120e6 * ep + 0.5 * 3.84e9 * ep * ep, 1e-3 * w);
}

// Pure kinematic hardening (β = 0): the yield surface translates, its radius stays σ_Y0, so on
// reversal the material yields again after an equivalent-stress change of 2σ_Y0 (Bauschinger).
TEST(J2Plasticity, KinematicHardeningTranslatesSurface) {
  const J2Plasticity j2 = J2Plasticity::from_young(69e9, 0.33, 120e6, 1e9, 0.0);
  J2Plasticity::State st;
  for (int i = 0; i < 100; ++i) j2.update(st, tension(0.01 / 100));
  EXPECT_NEAR(von_mises(st.s - st.back_stress), 120e6, 1e-3);
  EXPECT_GT(von_mises(st.s), 120e6 * 1.05);  // hardened in the loading direction
  EXPECT_NEAR(j2.yield_stress(st.plastic_strain), 120e6, 1e-9);
  const Mat3 s_before = st.s;
  const double reverse = 2.0 * 120e6 / (3.0 * j2.shear_modulus);
  const auto inc = j2.update(st, tension(-0.999 * reverse));
  EXPECT_EQ(inc.equivalent, 0.0);
  EXPECT_NEAR(von_mises(st.s - s_before), 0.999 * 2.0 * 120e6, 1e3);
  EXPECT_GT(j2.update(st, tension(-0.01 * reverse)).equivalent, 0.0);
}

// Uniaxial strain through SolidMaterial::update (linear EOS + J2, perfectly plastic): the axial
// stress at first yield is the Hugoniot elastic limit σ_HEL = (K + 4G/3)·Y/(2G) = Y(1 − ν)/(1 − 2ν)
// (e.g. Meyers, Dynamic Behavior of Materials, 1994, eq. 7.19): 541.6 MPa for E = 77.11 GPa,
// ν = 0.334, Y = 270 MPa. Beyond it dσ = K dε. Tolerance 0.2%: finite (log) strain vs small strain.
TEST(SolidMaterial, UniaxialStrainHugoniotElasticLimit) {
  const SolidMaterial m = elastic_plastic("al6061", 2703.0, 77.11e9, 0.334, 270e6);
  PointState p = m.initial_state();
  const double rate = -1e3, dt = 1e-9;  // ε̇_yy = −1000 /s
  Mat3 l = Mat3::Zero();
  l(1, 1) = rate;
  double sigma_at_yield = 0.0;
  for (int i = 0; i < 20000 && p.deviatoric.plastic_strain == 0.0; ++i) {
    sigma_at_yield = -p.stress()(1, 1);
    m.update(p, m.eos.rho0, l, dt, 0.0);
  }
  EXPECT_NEAR(sigma_at_yield, 541.6e6, 0.002 * 541.6e6);
  EXPECT_NEAR(von_mises(p.deviatoric.s), 270e6, 1e-6 * 270e6);
}

TEST(Library, SeedAluminiumAndCopper) {
  const SolidMaterial al = make_material("aluminium_seed000");
  EXPECT_DOUBLE_EQ(al.eos.rho0, 2700.0);
  EXPECT_DOUBLE_EQ(al.eos.c0, 5350.0);
  EXPECT_DOUBLE_EQ(al.eos.lambda, 1.34);
  EXPECT_DOUBLE_EQ(al.eos.gamma0, 1.96);
  EXPECT_NEAR(al.strength.shear_modulus, 69e9 / (2.0 * 1.33), 1.0);
  EXPECT_DOUBLE_EQ(al.strength.yield_stress0, 120e6);
  EXPECT_DOUBLE_EQ(al.strength.tangent_modulus, 384e6);
  EXPECT_DOUBLE_EQ(al.thermal.heat_capacity, 880.0);
  EXPECT_DOUBLE_EQ(al.thermal.conductivity, 237.0);
  EXPECT_DOUBLE_EQ(al.thermal.initial_temperature, 300.0);
  EXPECT_NO_THROW(al.validate());
  const SolidMaterial cu = make_material("copper");
  EXPECT_DOUBLE_EQ(cu.eos.rho0, 8930.0);
  EXPECT_NEAR(cu.strength.shear_modulus, 47.7e9, 1e3);
  EXPECT_NO_THROW(cu.validate());
  try {
    make_material("unobtainium");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("copper"), std::string::npos) << e.what();
  }
}
