// Tensile (spall) failure of one material point (materials/spall.hpp) under uniaxial-strain
// expansion, the loading of a spall plane: intact until the mean stress reaches −σ_sp, then no
// shear stress and no tension, compression carried again, and the energy equation consistent with
// the clipped stress.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/library.hpp"

using namespace shockfield;
using namespace shockfield::materials;

namespace {

constexpr double kRate = 1e6, kDt = 1e-10;  // uniaxial strain rate [1/s] and step [s]

// L = ±rate·e_y⊗e_y (uniaxial strain, as behind a plane wave).
Mat3 uniaxial(double rate) {
  Mat3 l = Mat3::Zero();
  l(1, 1) = rate;
  return l;
}

}  // namespace

TEST(SpallFailure, FailsAtTheSpallStrengthAndThenCarriesOnlyCompression) {
  SolidMaterial m = aluminium_seed000();
  m.spall.strength = 1e9;
  m.validate();
  PointState p = m.initial_state();
  const double rho0 = m.eos.rho0;
  double work =
      0.0;  // Σ v·σ:D·dt with the trapezoidal mean stress (what the energy equation integrates)
  bool failed = false;
  for (int i = 0; i < 4000 && !failed; ++i) {
    const double before = p.stress()(1, 1), v_old = p.deformation.determinant() / rho0;
    m.update(p, rho0, uniaxial(kRate), kDt, 1e-6);
    const double v_new = p.deformation.determinant() / rho0;
    work += 0.5 * (before + p.stress()(1, 1)) * (v_new - v_old);
    if (p.damage == 0.0) {
      EXPECT_GT(p.pressure + p.viscous_pressure, -1e9);  // intact only while above −σ_sp
    } else {
      failed = true;
      EXPECT_EQ(p.pressure, 0.0);
      EXPECT_EQ(p.deviatoric.s.norm(), 0.0);
    }
  }
  ASSERT_TRUE(failed);
  // Energy: e equals the work of the stress actually carried (trapezoidal, as the update integrates
  // it; 1e-5: dv against v̄·D·dt differ at O(dt²); without the clipping correction 7e-3).
  EXPECT_NEAR(p.energy, work, 1e-5 * std::abs(work));
  // Failed: further expansion carries no stress; recompression carries pressure again.
  for (int i = 0; i < 50; ++i) m.update(p, rho0, uniaxial(kRate), kDt, 1e-6);
  EXPECT_EQ(p.stress().norm(), 0.0);
  for (int i = 0; i < 400; ++i) m.update(p, rho0, uniaxial(-kRate), kDt, 1e-6);
  EXPECT_GT(p.pressure, 0.0);
  EXPECT_EQ(p.deviatoric.s.norm(), 0.0);
  EXPECT_EQ(p.damage, 1.0);
}

TEST(SpallFailure, OffByDefaultAndValidated) {
  SolidMaterial m = aluminium_seed000();
  EXPECT_FALSE(m.spall.enabled());
  PointState p = m.initial_state();
  for (int i = 0; i < 4000; ++i) m.update(p, m.eos.rho0, uniaxial(kRate), kDt, 1e-6);
  EXPECT_LT(p.pressure, -3e9);  // 4 % uniaxial expansion: tension carried in full without the model
  EXPECT_EQ(p.damage, 0.0);
  m.spall.strength = -1.0;
  EXPECT_THROW(m.validate(), InputError);
}

// Tuler–Butcher damage (spall.hpp): expand at a constant rate until the tensile mean stress is
// Δ above σ_0, then hold the volume (L = 0: P and e stay, q = 0). Below σ_0 no damage accumulates;
// during the hold D grows by Δ^λ·dt/K_f a step, so the point fails after (1 − D_0)·K_f/Δ^λ
// (analytic, to one step). A larger overstress fails sooner (the law's rate effect).
TEST(SpallFailure, TulerButcherFailsAfterTheDamageIntegral) {
  auto time_to_fail = [](double overstress) {
    SolidMaterial m = aluminium_seed000();
    m.spall.strength = 1e9;
    m.spall.tuler_butcher_exponent = 2.0;
    m.spall.tuler_butcher_integral = 1e9 * 1e9 * 5e-9;  // 5 ns at Δ = 1 GPa [Pa²·s]
    m.validate();
    PointState p = m.initial_state();
    const double rho0 = m.eos.rho0;
    int ramp = 0;
    while (-(p.pressure + p.viscous_pressure) < m.spall.strength + overstress && ramp++ < 100000) {
      if (-(p.pressure + p.viscous_pressure) < m.spall.strength) {
        EXPECT_EQ(p.damage, 0.0);
      }
      m.update(p, rho0, uniaxial(kRate), kDt, 1e-6);
    }
    const double d0 = p.damage, over = -p.pressure - m.spall.strength;
    EXPECT_LT(d0, 1.0);
    int steps = 0;
    while (p.damage < 1.0 && steps < 1000000) {
      m.update(p, rho0, Mat3::Zero(), kDt, 1e-6);
      ++steps;
    }
    const double expected = (1.0 - d0) * m.spall.tuler_butcher_integral / std::pow(over, 2.0);
    EXPECT_NEAR(steps * kDt, expected, kDt) << overstress;
    EXPECT_EQ(p.pressure, 0.0);  // failed as in the instantaneous criterion
    return expected;
  };
  const double slow = time_to_fail(0.5e9), fast = time_to_fail(1.0e9);
  EXPECT_GT(slow, 3.0 * fast);  // (1/0.5)² = 4 less what the ramps accumulated
}

TEST(SpallFailure, TulerButcherInputErrors) {
  SolidMaterial m = aluminium_seed000();
  m.spall.strength = 1e9;
  m.spall.tuler_butcher_exponent = 2.0;
  EXPECT_THROW(m.validate(), InputError);  // no K_f
  m.spall.tuler_butcher_integral = 1e9;
  EXPECT_NO_THROW(m.validate());
  m.spall.strength = 0.0;
  EXPECT_THROW(m.validate(), InputError);  // no threshold
  m.spall.strength = 1e9;
  m.spall.tuler_butcher_exponent = -1.0;
  EXPECT_THROW(m.validate(), InputError);
}
