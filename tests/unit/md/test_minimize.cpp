// FIRE with box relaxation: Cu_u3 (Foiles, Baskes & Daw 1986) gives the fitted lattice constant
// 3.615 Å and cohesive energy −3.54 eV/atom, starting from a strained and perturbed crystal.
#include <gtest/gtest.h>

#include "md_fixture.hpp"
#include "shockfield/md/minimize.hpp"

using namespace shockfield;
using namespace shockfield::md;

TEST(Minimize, CopperLatticeConstantAndCohesiveEnergy) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.70, {4, 4, 4}, box, 63.55);  // 2.4% too large
  fixture::perturb(atoms, 0.05, 17);
  Simulation s(box, std::move(atoms), fixture::cu_eam(), 0.002, 1.0);
  MinimizeSettings settings;
  settings.force_tolerance = 1e-6;
  settings.pressure_tolerance = 0.1;
  settings.relax_box = {true, true, true};
  const MinimizeResult r = minimize_fire(s, settings);
  ASSERT_TRUE(r.converged) << r.reason << " after " << r.iterations;
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(s.box.length()[d] / 4.0, 3.615, 5e-4);
  EXPECT_NEAR(r.energy / static_cast<double>(s.atoms.nlocal), -3.54, 5e-3);
}

TEST(Minimize, FixedBoxRelaxesOnlyTheAtoms) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {3, 3, 3}, box, 63.55);
  fixture::perturb(atoms, 0.1, 23);
  Simulation s(box, std::move(atoms), fixture::cu_eam(), 0.002, 1.0);
  const Vec3 l0 = s.box.length();
  const MinimizeResult r = minimize_fire(s, MinimizeSettings{});
  EXPECT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(s.box.length(), l0);
  EXPECT_LT(r.max_force, 1e-6);
}
