// Cu_u3.eam (Foiles, Baskes & Daw, PRB 33, 7983 (1986)) at 0 K: zero-pressure lattice constant,
// cohesive energy and cubic elastic constants from md::cubic_elastic_constants, against LAMMPS
// doing the same strains on the same potential (tests/fixtures/lammps_elastic: in.elastic,
// results.toml, regenerate.sh). Both codes tabulate and spline the funcfl file the same way and
// the fcc crystal has no internal relaxation, so the agreement is set by the relaxed a0 (both
// relax to |P| < 1e-4 bar: δa0/a0 ~ 1e-11) and round-off; we see 1e-11 relative, and check
// 1e-8 (the brief's target was 1e-6).
// The published fit targets (C11 = 1.67, C12 = 1.24, C44 = 0.76 Mbar; FBD 1986 Table I) are
// printed beside them and checked to the 2% the tabulated funcfl file reproduces them.
#include <gtest/gtest.h>

#include <cstdio>

#include "shockfield/core/config.hpp"
#include "shockfield/md/elastic_constants.hpp"
#include "shockfield/md/potentials/registry.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

CubicElasticConstants copper_u3() {
  CubicCrystal cu;
  cu.lattice.style = LatticeStyle::fcc;
  cu.lattice.a0 = 3.70;  // 2.4% too large: the relaxation must find a0
  cu.mass = {63.55};
  cu.type_names = {"Cu"};
  const PotentialFactory eam = [] {
    return potentials::make_potential(Config::parse("style = \"eam\"\nfile = \"Cu_u3.eam\"\n", "cu_u3.toml"), ".", 1);
  };
  return cubic_elastic_constants(cu, eam, ElasticSettings{});
}

}  // namespace

TEST(MdElastic, CopperU3MatchesLammps) {
  const Config lmp = Config::load("fixtures/lammps_elastic/results.toml");
  const CubicElasticConstants c = copper_u3();
  ASSERT_DOUBLE_EQ(lmp.get_double("strain"), ElasticSettings{}.strain);
  std::printf("                 shockfield          LAMMPS              FBD 1986\n"
              "a0 (A)           %.12f      %.12f      3.615\n"
              "E_coh (eV/atom)  %.12f     %.12f     -3.54\n"
              "C11 (GPa)        %.10f      %.10f      167\n"
              "C12 (GPa)        %.10f      %.10f      124\n"
              "C44 (GPa)        %.10f       %.10f       76\n",
              c.a0, lmp.get_double("a0_A"), c.cohesive_energy, lmp.get_double("cohesive_energy_eV"), c.c11,
              lmp.get_double("c11_GPa"), c.c12, lmp.get_double("c12_GPa"), c.c44, lmp.get_double("c44_GPa"));
  const auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
  EXPECT_LT(rel(c.a0, lmp.get_double("a0_A")), 1e-8);
  EXPECT_LT(rel(c.cohesive_energy, lmp.get_double("cohesive_energy_eV")), 1e-8);
  EXPECT_LT(rel(c.c11, lmp.get_double("c11_GPa")), 1e-8);
  EXPECT_LT(rel(c.c12, lmp.get_double("c12_GPa")), 1e-8);
  EXPECT_LT(rel(c.c44, lmp.get_double("c44_GPa")), 1e-8);
  EXPECT_LT(rel(c.c11, 167.0), 0.02);
  EXPECT_LT(rel(c.c12, 124.0), 0.02);
  EXPECT_LT(rel(c.c44, 76.0), 0.02);
}
