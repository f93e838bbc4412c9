// Liquid–vapour equations of state (seed eq. 19 and the GLS van der Waals form) and the Maxwell
// construction that is the reference for the GLS coexistence densities. Checks: the vdW critical
// point in closed form, the vdW coexistence at T/T_c = 0.9 (ρ_l/ρ_c = 1.6573,
// ρ_v/ρ_c = 0.4257), equal chemical potentials μ(ρ_v) = μ(ρ_l) from the free energies written
// out independently, the Carnahan–Starling critical point (b ρ_c = 0.5218, b T_c / a = 0.3773,
// Carnahan & Starling / the CS-LBM literature), the EOS derivative against finite differences,
// and densities outside the EOS domain.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/coexistence.hpp"
#include "shockfield/materials/eos/carnahan_starling.hpp"
#include "shockfield/materials/eos/van_der_waals.hpp"

using namespace shockfield;
using namespace shockfield::dbm;
using materials::CarnahanStarling;
using materials::VanDerWaals;

TEST(DbmCoexistence, VanDerWaalsCriticalPointAndMaxwell) {
  const VanDerWaals vdw;
  const CriticalPoint c = critical_point(vdw);
  EXPECT_NEAR(c.rho, 1.0, 1e-6);
  EXPECT_NEAR(c.T, 1.0, 1e-10);
  EXPECT_NEAR(c.p, 0.375, 1e-10);
  EXPECT_DOUBLE_EQ(vdw.critical_temperature(), 1.0);
  const Coexistence co = maxwell_construction(vdw, 0.9);
  EXPECT_NEAR(co.rho_liquid, 1.6573, 5e-5);
  EXPECT_NEAR(co.rho_vapour, 0.4257, 5e-5);
  const auto mu = [&](double r) {
    return 0.9 * (std::log(r / (1 - vdw.b * r)) + vdw.b * r / (1 - vdw.b * r)) - 2 * vdw.a * r;
  };
  EXPECT_NEAR(mu(co.rho_liquid), mu(co.rho_vapour), 1e-9);
  EXPECT_NEAR(vdw.pressure(co.rho_liquid, 0.9), co.p_saturation, 1e-12);
}

TEST(DbmCoexistence, CarnahanStarlingCriticalPointAndMaxwell) {
  const CarnahanStarling cs{0.5, 4.0};
  const CriticalPoint c = critical_point(cs);
  EXPECT_NEAR(c.rho * cs.b, 0.5218, 1e-4);
  EXPECT_NEAR(c.T * cs.b / cs.a, 0.3773, 1e-4);
  const double T = 0.9 * c.T;
  const Coexistence co = maxwell_construction(cs, T);
  EXPECT_GT(co.rho_liquid, c.rho);
  EXPECT_LT(co.rho_vapour, c.rho);
  const auto mu = [&](double r) {
    const double e = cs.b * r / 4, s = 1 - e;
    return T * (std::log(r) + (8 * e - 9 * e * e + 3 * e * e * e) / (s * s * s)) - 2 * cs.a * r;
  };
  EXPECT_NEAR(mu(co.rho_liquid), mu(co.rho_vapour), 1e-9);
  EXPECT_NEAR(cs.pressure(co.rho_vapour, T), cs.pressure(co.rho_liquid, T), 1e-12);
}

TEST(DbmCoexistence, DerivativesAndDomain) {
  const VanDerWaals vdw;
  const CarnahanStarling cs{0.5, 4.0};
  const double h = 1e-6;
  for (double r : {0.3, 1.0, 2.2}) {
    EXPECT_NEAR(vdw.dpressure_drho(r, 0.9),
                (vdw.pressure(r + h, 0.9) - vdw.pressure(r - h, 0.9)) / (2 * h), 1e-6);
    EXPECT_NEAR(cs.dpressure_drho(r / 4, 0.1),
                (cs.pressure(r / 4 + h, 0.1) - cs.pressure(r / 4 - h, 0.1)) / (2 * h), 1e-6);
  }
  try {
    vdw.pressure(3.2, 0.9);
    FAIL() << "density beyond 1/b accepted";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("density 3.2 must be in (0, 3)"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(cs.pressure(1.0, 0.1), RunError);   // η = 1
  EXPECT_THROW(cs.pressure(0.1, -1.0), RunError);  // T < 0
  EXPECT_THROW((VanDerWaals{-1.0, 1.0 / 3}.validate("[dbm.eos]")), InputError);
  EXPECT_THROW((CarnahanStarling{1.0, 0.0}.validate("[dbm.eos]")), InputError);
}
