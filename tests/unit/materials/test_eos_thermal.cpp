// Mie-Grüneisen EOS (Xu et al. 2015, eqs. 5-6), temperature (eqs. 7-8) and artificial viscosity.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/artificial_viscosity.hpp"
#include "shockfield/materials/eos/mie_gruneisen.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/materials/thermal.hpp"

using namespace shockfield;
using namespace shockfield::materials;

// On the Hugoniot (e = E_H) the pressure is P_H, and the Rankine-Hugoniot jump conditions of the
// linear Us-Up fit hold: ρ = ρ0·Us/(Us − Up), P = ρ0·Us·Up (exact algebra, tolerance round-off).
TEST(MieGruneisen, PressureOnHugoniotMatchesUsUpJump) {
  const MieGruneisen eos = aluminium_seed000().eos;
  for (double up : {100.0, 500.0, 1000.0, 3000.0}) {
    const double us = eos.shock_speed(up);
    const double rho = eos.rho0 * us / (us - up);
    const double p = eos.pressure(rho, eos.hugoniot_energy(rho));
    EXPECT_NEAR(p, eos.rho0 * us * up, 1e-10 * eos.rho0 * us * up) << "Up = " << up;
    // E_H = ½Up² (energy jump of a shock from rest).
    EXPECT_NEAR(eos.hugoniot_energy(rho), 0.5 * up * up, 1e-10 * up * up);
  }
}

// Seed §4.1 aluminium at Up = 1000 m/s: the reference 18.06 GPa and 3174 kg/m³.
TEST(MieGruneisen, AluminiumAt1000MetresPerSecond) {
  const MieGruneisen eos = aluminium_seed000().eos;
  const double rho = eos.rho0 * 6690.0 / 5690.0;
  EXPECT_NEAR(rho, 3174.5, 0.1);
  EXPECT_NEAR(eos.hugoniot_pressure(rho), 18.063e9, 1e6);
}

// Tension branch of eq. 6 continues the compression branch: P = ρ0c0²η with the same slope at ρ0.
TEST(MieGruneisen, TensionBranchIsLinearAndContinuous) {
  const MieGruneisen eos = aluminium_seed000().eos;
  const double k = eos.bulk_modulus();
  const double rho = 0.99 * eos.rho0;
  EXPECT_NEAR(eos.hugoniot_pressure(rho), k * (1.0 - eos.rho0 / rho), 1e-6 * k);
  EXPECT_LT(eos.hugoniot_pressure(rho), 0.0);
  const double d = 1e-7 * eos.rho0;
  const double slope_c = (eos.hugoniot_pressure(eos.rho0 + d) - eos.hugoniot_pressure(eos.rho0)) / d;
  const double slope_t = (eos.hugoniot_pressure(eos.rho0) - eos.hugoniot_pressure(eos.rho0 - d)) / d;
  EXPECT_NEAR(slope_c, slope_t, 1e-4 * slope_t);
}

// Energy dependence: ∂P/∂e = ργ = ρ0γ0 (eq. 5).
TEST(MieGruneisen, EnergyDependence) {
  const MieGruneisen eos = aluminium_seed000().eos;
  const double rho = 3000.0;
  EXPECT_NEAR(eos.pressure(rho, 2e5) - eos.pressure(rho, 1e5), 1e5 * eos.rho0 * eos.gamma0, 1e-3);
}

// Sound speed: c = c0 at the reference state; elsewhere c² = dP/dρ along the isentrope
// de = P/ρ² dρ, checked by a central difference (tolerance: truncation error O(δ²)).
TEST(MieGruneisen, SoundSpeedIsIsentropicDerivative) {
  const MieGruneisen eos = aluminium_seed000().eos;
  EXPECT_NEAR(eos.sound_speed(eos.rho0, 0.0), eos.c0, 1e-9 * eos.c0);
  for (double rho : {2600.0, 3000.0, 3500.0}) {
    const double e = 3e5;
    const double p = eos.pressure(rho, e);
    const double d = 1e-4 * rho;
    const double de = p / (rho * rho) * d;
    const double c2 = (eos.pressure(rho + d, e + de) - eos.pressure(rho - d, e - de)) / (2.0 * d);
    EXPECT_NEAR(eos.sound_speed(rho, e), std::sqrt(c2), 1e-5 * std::sqrt(c2)) << rho;
  }
}

TEST(MieGruneisen, RejectsBadParameters) {
  MieGruneisen eos{2700.0, -1.0, 1.3, 2.0};
  try {
    eos.validate("test");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c0"), std::string::npos) << e.what();
  }
  MieGruneisen ok = aluminium_seed000().eos;
  EXPECT_THROW(ok.pressure(ok.rho0 * 10.0, 0.0), RunError);  // beyond η = 1/λ
}

// Eq. 7 integrated independently here by classical RK4 in V (2000 steps), against the model's
// incremental RK2 in 200 steps: agreement within 0.1 K.
TEST(Thermal, HugoniotTemperatureMatchesEq7) {
  const SolidMaterial al = aluminium_seed000();
  const MieGruneisen& eos = al.eos;
  const double cv = al.thermal.heat_capacity, v0 = 1.0 / eos.rho0, v1 = 1.0 / 3174.5;
  auto rhs = [&](double v, double t) {
    const double l = eos.lambda;
    const double den = (l - 1.0) * v0 - l * v;
    return eos.c0 * eos.c0 * l * (v0 - v) * (v0 - v) / (cv * den * den * den) - eos.rho0 * eos.gamma0 * t;
  };
  double t_ref = 300.0;
  const int n = 2000;
  const double h = (v1 - v0) / n;
  for (int i = 0; i < n; ++i) {
    const double v = v0 + i * h;
    const double k1 = rhs(v, t_ref), k2 = rhs(v + h / 2, t_ref + h / 2 * k1), k3 = rhs(v + h / 2, t_ref + h / 2 * k2),
                 k4 = rhs(v + h, t_ref + h * k3);
    t_ref += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  double t = 300.0, vs = v0;
  for (int i = 0; i < 200; ++i)
    t = al.thermal.advance(eos, v0 + i * (v1 - v0) / 200, v0 + (i + 1) * (v1 - v0) / 200, t, 0.0, vs);
  EXPECT_NEAR(t, t_ref, 0.1);
  EXPECT_EQ(vs, v1);
  // Ringing below the shock volume (expand, recompress to v1) is isentropic and reversible.
  const double t_shocked = t;
  for (int i = 0; i < 50; ++i) {
    t = al.thermal.advance(eos, v1, v1 * 1.01, t, 0.0, vs);
    t = al.thermal.advance(eos, v1 * 1.01, v1, t, 0.0, vs);
  }
  EXPECT_NEAR(t, t_shocked, 1e-6 * t_shocked);
  EXPECT_GT(t_ref, 330.0);  // a 18 GPa shock heats aluminium by tens of kelvin
}

// Expansion follows the isentrope T = T0·exp(−ρ0γ0ΔV) (γ/V = ρ0γ0), plastic work adds dW/c_v (eq. 8).
TEST(Thermal, IsentropicReleaseAndPlasticWork) {
  const SolidMaterial al = aluminium_seed000();
  const double v0 = 1.0 / 3174.5, v1 = 1.0 / 2700.0;
  double t = 400.0, vs = v0;
  for (int i = 0; i < 100; ++i)
    t = al.thermal.advance(al.eos, v0 + i * (v1 - v0) / 100, v0 + (i + 1) * (v1 - v0) / 100, t, 0.0, vs);
  EXPECT_NEAR(t, 400.0 * std::exp(-al.eos.rho0 * al.eos.gamma0 * (v1 - v0)), 1e-3);
  EXPECT_NEAR(al.thermal.advance(al.eos, v0, v0, 300.0, 880.0, vs), 301.0, 1e-12);
}

// q = ρℓ(C_Q ℓ(∇·v)² − C_L c ∇·v) in compression, 0 in expansion, with the defaults C_Q = 2 and
// C_L = 1 (0.3 before the deviator fix of issue 16, docs/theory/mpm.md).
TEST(ArtificialViscosity, LinearPlusQuadraticInCompressionOnly) {
  const ArtificialViscosity av;
  EXPECT_EQ(av.pressure(2700.0, 5000.0, 1e6, 1e-3), 0.0);
  EXPECT_NEAR(av.pressure(2700.0, 5000.0, -1e6, 1e-3), 2700.0 * 1e-3 * (2.0 * 1e-3 * 1e12 + 1.0 * 5000.0 * 1e6), 1e-3);
}
