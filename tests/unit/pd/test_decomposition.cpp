// A pd body on the rank grid (pd/decomposition.hpp), the parts that one rank can check in every
// build: the rank grid chosen for a body and horizon and the refusal of more ranks than pieces at
// least δ long; and a one-rank decomposition, which holds the whole body in index order with the
// whole family, so that gathering its state gives back the state bitwise. The decomposed runs on
// 1, 2 and 4 ranks are tests/mpi/pd_ranks.sh (label mpi).
#include <gtest/gtest.h>

#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/decomposition.hpp"
#include "shockfield/pd/run_ranks.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {
std::string refusal(const PointCloud& cloud, double horizon, int ranks, const parallel::Dims3& given = {0, 0, 0}) {
  try {
    pd_rank_grid(cloud, horizon, ranks, given);
  } catch (const InputError& e) {
    return e.what();
  }
  return "not refused";
}
}  // namespace

TEST(PdRankGrid, ChoosesTheLeastHaloAndRefusesPiecesShorterThanTheHorizon) {
  // 40 x 24 mm (each point's 1 mm cell), δ = 3.015 mm: 13 x 7 pieces fit.
  const PointCloud plate = lattice_cloud(2, {40, 24, 1}, 1e-3);
  EXPECT_EQ(pd_rank_grid(plate, 3.015e-3, 2, {0, 0, 0}), (parallel::Dims3{2, 1, 1}));  // the shorter cut face
  EXPECT_EQ(pd_rank_grid(plate, 3.015e-3, 4, {2, 2, 1}), (parallel::Dims3{2, 2, 1}));
  EXPECT_NE(refusal(plate, 3.015e-3, 8, {1, 8, 1}).find("as --rank-grid 1x8x1; at most 13 x 7 x 1 = 91 ranks fit"),
            std::string::npos);
  // A bar of 10 points 50 µm apart (0.5 mm) with δ = 150.75 µm: 3 pieces.
  const std::string bar = refusal(lattice_cloud(1, {10, 1, 1}, 50e-6), 150.75e-6, 4);
  EXPECT_NE(bar.find("4 ranks cannot cut the body (0.0005 x 5e-05 x 5e-05 m) into pieces at least 0.0001508 m long"),
            std::string::npos)
      << bar;
  EXPECT_NE(bar.find("at most 3 x 1 x 1 = 3 ranks fit"), std::string::npos) << bar;
}

TEST(PdDecomposition, OneRankHoldsTheWholeBodyAndGathersItBack) {
  const PointCloud cloud = lattice_cloud(2, {12, 9, 1}, 1e-3);
  const Family family = build_family(cloud, 3.015e-3, VolumeCorrection::linear);
  const Decomposition domain(parallel::Communicator::single(), {1, 1, 1}, cloud, family);
  ASSERT_EQ(domain.owned(), cloud.size());
  ASSERT_EQ(domain.cloud().size(), cloud.size());  // no ghosts: no axis is cut
  EXPECT_EQ(domain.family().offset, family.offset);
  EXPECT_EQ(domain.family().neighbor, family.neighbor);
  EXPECT_EQ(domain.family().length, family.length);
  EXPECT_EQ(domain.family().volume_scale, family.volume_scale);
  for (std::size_t b = 0; b < family.bonds(); ++b) ASSERT_EQ(domain.bond_origin()[b], b);

  // A whole body after some broken bonds: dealt out, then gathered into a fresh whole, bitwise.
  auto make = [&](const PointCloud& c, const Family& f) {
    return std::make_unique<LpsForce>(c, f, LpsModel{158e9, 73e9, 2}, Influence(), CriticalStretch{1e-3, 0.25});
  };
  Simulation whole(cloud, family, make(cloud, family), {8000.0});
  for (std::size_t i = 0; i < cloud.size(); ++i) whole.velocities()[i] = Vec3(0.0, 3e4 * (cloud.x[i][1] - 4e-3), 0.0);
  for (int k = 0; k < 5; ++k) whole.step(5e-8);
  auto* whole_force = dynamic_cast<LpsForce*>(&whole.model());
  ASSERT_LT(whole_force->intact_bonds(), family.bonds());  // bonds broke
  Simulation local(domain.cloud(), domain.family(), make(domain.cloud(), domain.family()), {8000.0});
  deal_out(domain, whole, local);
  const ModelState state = local_state(domain, whole_force->saved_state());
  Simulation back(cloud, family, make(cloud, family), {8000.0});
  ModelState gathered = dynamic_cast<LpsForce*>(&back.model())->saved_state();
  gather_whole(domain, local, state, back, gathered);
  EXPECT_EQ(back.positions(), whole.positions());
  EXPECT_EQ(back.velocities(), whole.velocities());
  EXPECT_EQ(back.force_density(), whole.force_density());
  EXPECT_EQ(back.step_count(), 5);
  EXPECT_EQ(gathered, whole_force->saved_state());
}
