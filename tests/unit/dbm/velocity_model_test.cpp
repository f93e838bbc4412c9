// Discrete velocity model: f^eq = C⁻¹·M^eq satisfies the seven moment relations (seed eqs.
// 20–26) computed independently from the velocities; models that cannot are refused.
#include <gtest/gtest.h>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/velocity_model.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

TEST(DbmVelocityModel, EquilibriumSatisfiesSevenMomentRelations) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  const MomentInversion inversion(model);
  for (double gamma : {1.4, 5.0 / 3.0, 2.0}) {
    const double b = 2.0 / (gamma - 1.0);
    const double rho = 0.7, ux = 0.3, uy = -0.2, T = 1.3;
    std::vector<double> f(16);
    inversion.equilibrium(rho, ux, uy, T, b, f.data());
    double m0 = 0, m1x = 0, e = 0, m2xy = 0, m2yy = 0, m3xxy = 0, m31x = 0, m42xx = 0;
    for (int k = 0; k < 16; ++k) {
      const double vx = model.vx[k], vy = model.vy[k], eta = model.eta[k];
      const double half = 0.5 * (vx * vx + vy * vy + eta * eta);
      m0 += f[k];
      m1x += f[k] * vx;
      e += f[k] * half;
      m2xy += f[k] * vx * vy;
      m2yy += f[k] * vy * vy;
      m3xxy += f[k] * vx * vx * vy;
      m31x += f[k] * half * vx;
      m42xx += f[k] * half * vx * vx;
    }
    const double u2 = ux * ux + uy * uy;
    EXPECT_NEAR(m0, rho, 1e-12);                                    // eq. 20
    EXPECT_NEAR(m1x, rho * ux, 1e-12);                              // eq. 21
    EXPECT_NEAR(e, 0.5 * rho * (b * T + u2), 1e-11);                // eq. 22
    EXPECT_NEAR(m2xy, rho * ux * uy, 1e-12);                        // eq. 23
    EXPECT_NEAR(m2yy, rho * (T + uy * uy), 1e-12);                  // eq. 23
    EXPECT_NEAR(m3xxy, rho * (T * uy + ux * ux * uy), 1e-11);       // eq. 24
    EXPECT_NEAR(m31x, 0.5 * rho * ux * ((b + 2) * T + u2), 1e-11);  // eq. 25
    EXPECT_NEAR(m42xx, 0.5 * rho * (((b + 2) * T + u2) * T + ((b + 4) * T + u2) * ux * ux),
                1e-10);  // eq. 26
  }
  // b = 2 (γ = 2) reproduces the paper's forms, e.g. eq. 26: ρ[(2T + u²/2)T + uu(3T + u²/2)].
  std::vector<double> f(16);
  inversion.equilibrium(1.0, 0.5, 0.0, 1.0, 2.0, f.data());
  double m42xx = 0;
  for (int k = 0; k < 16; ++k)
    m42xx += f[k] * 0.5 * (model.vx[k] * model.vx[k] + model.vy[k] * model.vy[k] +
                           model.eta[k] * model.eta[k]) * model.vx[k] * model.vx[k];
  EXPECT_NEAR(m42xx, (2 + 0.125) * 1 + 0.25 * (3 + 0.125), 1e-11);
}

TEST(DbmVelocityModel, MacroscopicStateRoundTrips) {
  const VelocityModel model = d2v16({3.0, 2.0, 5.0, 10.0}, 8.0);
  const MomentInversion inversion(model);
  std::vector<double> f(16);
  inversion.equilibrium(0.445, 0.698, -0.1, 7.928, 5.0, f.data());
  const Macro m = macro_of(model, f.data(), 1, 5.0);
  EXPECT_NEAR(m.rho, 0.445, 1e-12);
  EXPECT_NEAR(m.ux, 0.698, 1e-12);
  EXPECT_NEAR(m.uy, -0.1, 1e-12);
  EXPECT_NEAR(m.T, 7.928, 1e-10);
}

TEST(DbmVelocityModel, RefusesModelsThatCannotSatisfyTheMoments) {
  // Equal speeds on the two diagonal groups make columns of C repeat: singular.
  try {
    MomentInversion bad(d2v16({1.0, 2.0, 3.0, 2.0}, 2.0));
    FAIL() << "singular model accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot satisfy the seven moment relations"),
              std::string::npos)
        << e.what();
  }
  // eta0 = 0 leaves the energy moment eq. 22 dependent on the trace of eq. 23.
  EXPECT_THROW(MomentInversion(d2v16({1.0, 2.0, 3.0, 4.0}, 0.0)), InputError);
  // A D2Q9-like set has too few velocities for 16 moment components.
  VelocityModel small = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  small.vx.resize(9), small.vy.resize(9), small.eta.resize(9);
  try {
    MomentInversion bad(small);
    FAIL() << "9-velocity model accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs exactly 16 velocities"), std::string::npos)
        << e.what();
  }
}

TEST(DbmVelocityModel, MirrorImagesForReflectingWalls) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  for (int axis = 0; axis < 2; ++axis) {
    const auto map = model.mirror(axis);
    for (int k = 0; k < 16; ++k) {
      EXPECT_DOUBLE_EQ(model.vx[map[k]], axis == 0 ? -model.vx[k] : model.vx[k]);
      EXPECT_DOUBLE_EQ(model.vy[map[k]], axis == 1 ? -model.vy[k] : model.vy[k]);
      EXPECT_EQ(map[map[k]], k);
    }
  }
  VelocityModel lopsided = model;
  lopsided.vx[0] += 0.1;
  EXPECT_THROW(lopsided.mirror(0), InputError);
}
