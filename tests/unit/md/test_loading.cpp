// Loading fixes: the piston reflects atoms as a moving mirror; deformation rescales the box and
// coordinates affinely at the prescribed engineering strain rate.
#include <gtest/gtest.h>

#include "md_fixture.hpp"
#include "shockfield/md/fixes/deform.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/fixes/piston.hpp"

using namespace shockfield;
using namespace shockfield::md;

TEST(Piston, ReflectsAnAtomOffTheMovingWall) {
  // One atom approaching a wall that moves at +2 Å/ps from z = 0: after the reflection its
  // velocity is 2·u_p − v and it sits mirrored in front of the wall.
  geometry::Box box;
  box.lo = Vec3(0, 0, -10);
  box.hi = Vec3(20, 20, 10);
  box.boundary = {geometry::Boundary::periodic, geometry::Boundary::periodic, geometry::Boundary::shrink};
  Atoms atoms;
  atoms.mass = {63.55};
  atoms.type_names = {"Cu"};
  atoms.add(Vec3(5, 5, 0.05), 0, 1, Vec3(0, 0, -3.0));
  atoms.add(Vec3(5, 5, 9.0), 0, 2);
  Simulation s(box, std::move(atoms), fixture::argon_lj(), 0.01, 1.0);
  s.fixes.push_back(std::make_unique<FixNve>());
  s.fixes.push_back(std::make_unique<FixPiston>(2, +1, 2.0, 0.0, 0.0));
  s.setup(false);
  s.advance([](std::int64_t) { return false; });
  // Drift: z = 0.05 − 0.03 = 0.02; wall at 0.02 → not behind yet (z ≥ w). One more step:
  s.advance([](std::int64_t) { return false; });
  // z = 0.02 − 0.03 = −0.01, wall at 0.04: reflected to 0.09, v = 4 − (−3) = 7 Å/ps.
  EXPECT_NEAR(s.atoms.x[0].z(), 0.09, 1e-9);
  EXPECT_NEAR(s.atoms.v[0].z(), 7.0, 1e-6);
  const auto* piston = dynamic_cast<const FixPiston*>(s.fixes[1].get());
  EXPECT_NEAR(piston->wall(s.time), 0.04, 1e-12);
  // Work done by the wall: ½ m (7² − 3²) in eV.
  EXPECT_NEAR(piston->energy_added(), 0.5 * 63.55 * 40.0 * 1.0364269e-4, 1e-6);
}

TEST(Deform, BoxAndAtomsFollowTheStrainRate) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {3, 3, 3}, box, 63.55);
  const Vec3 l0 = box.length();
  const Vec3 x0 = atoms.x[5];
  Simulation s(box, std::move(atoms), fixture::cu_eam(), 0.001, 1.0);
  const Vec3 rate(0.5, 0.0, -0.2);  // 1/ps
  s.fixes.push_back(std::make_unique<FixDeform>(rate, Vec3::Zero(), s.box, 0.0));
  s.setup(false);
  // With no integrator the atoms only move with the box.
  for (int k = 0; k < 100; ++k) s.advance([](std::int64_t) { return false; });
  const double t = 0.1;
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(s.box.length()[d], l0[d] * (1 + rate[d] * t), 1e-10);
    const double centre = 0.5 * l0[d];
    EXPECT_NEAR(s.atoms.x[5][d], centre + (x0[d] - centre) * (1 + rate[d] * t), 1e-9);
  }
}

// The shrink-wrap margin is LAMMPS's Domain::small: 1e-4 × the box length the simulation was
// created with, kept as the atoms spread (not 1e-4 × the atoms' extent, which it was before).
TEST(ShrinkWrap, MarginIsOneTenThousandthOfTheInitialBoxLength) {
  geometry::Box box;
  box.lo = Vec3(0, 0, -10);
  box.hi = Vec3(20, 20, 30);  // z: 40 Å long → margin 4e-3 Å; the atoms span 9 Å
  box.boundary = {geometry::Boundary::periodic, geometry::Boundary::periodic, geometry::Boundary::shrink};
  Atoms atoms;
  atoms.mass = {63.55};
  atoms.add(Vec3(5, 5, 0), 0, 1, Vec3(0, 0, -1.0));
  atoms.add(Vec3(5, 5, 9.0), 0, 2);
  Simulation s(box, std::move(atoms), fixture::argon_lj(), 0.01, 1.0);
  s.fixes.push_back(std::make_unique<FixNve>());
  s.setup(false);
  EXPECT_DOUBLE_EQ(s.box.lo.z(), 0 - 4e-3);
  EXPECT_DOUBLE_EQ(s.box.hi.z(), 9 + 4e-3);
  EXPECT_EQ(s.box.lo.x(), 0.0);  // periodic: untouched
  for (int k = 0; k < 80; ++k) s.advance([](std::int64_t) { return false; });  // atom 1 moves 0.8 Å down
  s.rebuild();
  EXPECT_NEAR(s.box.lo.z(), s.atoms.x[0].z() - 4e-3, 1e-12);
}
