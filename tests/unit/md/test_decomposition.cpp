// MD's rank grid (md/decomposition.hpp) on one rank: the refusals, and a Decomposition of one
// rank — every ghost made by a swap to itself and every ghost value moved by the swaps instead of
// the owner indices of the serial path — against the serial path (the multi-rank runs:
// tests/mpi/md_ranks_mpi.cpp).
#include <gtest/gtest.h>

#include "md_fixture.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/fixes/nve.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {
std::string refusal(const geometry::Box& box, double range, int ranks, parallel::Dims3 given = {0, 0, 0}) {
  try {
    md_rank_grid(box, range, ranks, given);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(MdRankGrid, ChoosesTheGridWithTheLeastHalo) {
  geometry::Box box;
  fixture::fcc_atoms(3.615, {20, 20, 10}, box, 63.55);  // 72.3 x 72.3 x 36.15 Å
  const parallel::Dims3 two = md_rank_grid(box, 5.95, 2, {0, 0, 0});
  EXPECT_EQ(two[0] * two[1] * two[2], 2);
  EXPECT_EQ(two[2], 1);  // cutting the thin axis would double the face
  EXPECT_EQ(md_rank_grid(box, 5.95, 4, {1, 1, 4}), (parallel::Dims3{1, 1, 4}));  // given, and it fits
  fixture::fcc_atoms(3.615, {24, 24, 24}, box, 63.55);
  // 8 ranks on a cube: 2 x 2 x 2 blocks have 1.5 L² of faces each, 8 slabs 2 L².
  EXPECT_EQ(md_rank_grid(box, 5.95, 8, {0, 0, 0}), (parallel::Dims3{2, 2, 2}));
}

TEST(MdRankGrid, RefusesMoreRanksThanTheBoxCanBeCutIntoForTheCutoff) {
  geometry::Box box;
  fixture::fcc_atoms(3.615, {3, 3, 3}, box, 63.55);  // 10.8 Å: one piece of 5.95 Å per axis
  const std::string chosen = refusal(box, 5.95, 2);
  EXPECT_NE(chosen.find("2 ranks cannot cut the box (10.85 x 10.85 x 10.85 Å)"), std::string::npos) << chosen;
  EXPECT_NE(chosen.find("at most 1 x 1 x 1 = 1 ranks fit"), std::string::npos) << chosen;
  fixture::fcc_atoms(3.615, {6, 6, 6}, box, 63.55);
  const std::string given = refusal(box, 5.95, 4, {4, 1, 1});
  EXPECT_NE(given.find("as --rank-grid 4x1x1"), std::string::npos) << given;
  EXPECT_NE(refusal(box, 5.95, 4, {2, 1, 1}).find("has 2 ranks, the run has 4"), std::string::npos);
  box.tilt = Vec3(1.0, 0, 0);
  EXPECT_NE(refusal(box, 5.95, 2).find("triclinic box runs on one rank only"), std::string::npos);
}

// One rank through the decomposition: the same forces and energy to round-off (the ghost forces
// and EAM densities are summed back swap by swap, not straight onto the owner: a different order),
// and 20 NVE steps later the same thermo.
TEST(MdDecomposition, OneRankEqualsTheSerialPathToRoundOff) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {4, 4, 4}, box, 63.55);  // 14.5 Å: one image layer
  fixture::perturb(atoms, 0.1, 3);
  // A drift of 27 Å/ps (0.05 Å per step, through the periodic faces) and some thermal motion.
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    atoms.v[i] = Vec3(20.0, -15.0, 10.0) + Vec3(1.0, -2.0, 0.5) * (static_cast<double>(i % 7) - 3.0);
  Simulation serial(box, atoms, fixture::cu_eam(), 0.002, 1.0);
  Simulation split(box, atoms, fixture::cu_eam(), 0.002, 1.0);
  split.domain = std::make_shared<Decomposition>(parallel::Communicator::single(), parallel::Dims3{1, 1, 1}, box, 5.95);
  for (Simulation* s : {&serial, &split}) {
    s->fixes.push_back(std::make_unique<FixNve>());
    s->setup(false);
  }
  ASSERT_NE(split.atoms.ranks, nullptr);
  ASSERT_EQ(split.atoms.nghost(), serial.atoms.nghost());  // the same swaps, the same ghosts
  double worst = 0;
  for (std::size_t i = 0; i < serial.atoms.nlocal; ++i) worst = std::max(worst, (split.atoms.f[i] - serial.atoms.f[i]).norm());
  // Sums of ~50 terms of ~1 eV/Å in another order: ~1e-15 eV/Å; a missed pair would be > 1e-3.
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(split.forces.energy, serial.forces.energy, 1e-12 * std::abs(serial.forces.energy));
  for (int step = 0; step < 20; ++step)
    for (Simulation* s : {&serial, &split}) s->advance([](std::int64_t) { return false; });
  EXPECT_GT(split.rebuilds, 1);  // 1 Å in 20 steps: the ghosts were rebuilt (skin 1 Å)
  const ThermoState a = serial.thermo(), b = split.thermo();
  EXPECT_NEAR(b.potential, a.potential, 1e-10 * std::abs(a.potential));
  EXPECT_NEAR(b.kinetic, a.kinetic, 1e-10 * std::abs(a.kinetic));
  EXPECT_NEAR(b.pressure, a.pressure, 1e-8 * std::max(1.0, std::abs(a.pressure)));
}
