// FIRE with box relaxation: Cu_u3 (Foiles, Baskes & Daw 1986) gives the fitted lattice constant
// 3.615 Å and cohesive energy −3.54 eV/atom, starting from a strained and perturbed crystal.
#include <gtest/gtest.h>

#include <map>

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

// A frozen group stays exactly where it was; the others relax (max |f| over them only).
TEST(Minimize, AtomsOutsideTheGroupStayPut) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {3, 3, 3}, box, 63.55);
  fixture::perturb(atoms, 0.1, 29);
  constexpr std::uint32_t kMobile = 1u << 1;
  std::map<std::int64_t, Vec3> before;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    atoms.mask[i] = 1u | (atoms.id[i] % 2 ? kMobile : 0u);
    before[atoms.id[i]] = atoms.x[i];
  }
  Simulation s(box, std::move(atoms), fixture::cu_eam(), 0.002, 1.0);
  MinimizeSettings settings;
  settings.group = kMobile;
  const MinimizeResult r = minimize_fire(s, settings);
  EXPECT_TRUE(r.converged) << r.reason;
  double moved = 0;
  for (std::size_t i = 0; i < s.atoms.nlocal; ++i) {
    // Positions may have been wrapped into the box: compare through the minimum image (round-off).
    const double shift = s.box.minimum_image(s.atoms.x[i] - before.at(s.atoms.id[i])).norm();
    if (s.atoms.id[i] % 2 == 0) {
      EXPECT_LT(shift, 1e-12) << "frozen atom " << s.atoms.id[i] << " moved";
    } else {
      moved = std::max(moved, shift);
      EXPECT_LT(s.atoms.f[i].norm(), 1e-6);
    }
  }
  EXPECT_GT(moved, 1e-3);  // the mobile atoms did relax (perturbation 0.1 Å)
}
