// The same horizontal chain run by LAMMPS (gran/hertz/history, no damping, no tangential force,
// fix nve/sphere: velocity Verlet as here) and by the granular Simulation at the same step:
// displacements and velocities of every grain at every stored frame agree to round-off.
// Fixture and script: fixtures/lammps_granular/ (in.chain, dump.chain, regenerate.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "shockfield/granular/simulation.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::granular {
namespace {

TEST(GranularLammpsPeer, TrajectoriesOfEveryGrainMatchGranHertzHistory) {
  const auto frames = io::read_dump("fixtures/lammps_granular/dump.chain");
  ASSERT_EQ(frames.size(), 11u);
  ChainSpec s;  // in.chain: 100 steel spheres, R = 5 mm, E = 200 GPa, ν = 0.3, ρ = 7850
  s.grains = 100;
  s.radius = 5e-3;
  Simulation sim(build_chain(s), Impulse{Impulse::Kind::velocity, 0.1, 1, {}, {}}, 2e-8);
  const std::vector<double>& x0 = frames[0].column("x");
  double worst_w = 0, worst_v = 0, w_scale = 0, v_scale = 0;
  for (const auto& frame : frames) {
    while (sim.step_count() < frame.timestep) sim.step();
    const auto& x = frame.column("x");
    const auto& vx = frame.column("vx");
    const auto ids = frame.ids();
    for (std::size_t r = 0; r < frame.natoms(); ++r) {
      const auto i = static_cast<std::size_t>(ids[r] - 1);
      worst_w = std::max(worst_w, std::abs((x[r] - x0[r]) - sim.displacement()[i]));
      worst_v = std::max(worst_v, std::abs(vx[r] - sim.velocity()[i]));
      w_scale = std::max(w_scale, std::abs(sim.displacement()[i]));
      v_scale = std::max(v_scale, std::abs(sim.velocity()[i]));
    }
  }
  // Same integrator and step: the difference is round-off. LAMMPS forms overlaps from absolute
  // positions (|x| ≤ 1 m: ε|x| ≈ 1e-16 m against overlaps of ~1e-6 m, 1e-10 of each force), and
  // 1e5 steps carry it forward (at most ~1e-5 if every step's error added up). Measured 1.2e-7
  // of the largest displacement; κ off by 1e-4 gives 4.2e-4 (checked by hand), so 1e-6 tells a
  // model difference from round-off.
  EXPECT_LT(worst_w, 1e-6 * w_scale);
  EXPECT_LT(worst_v, 1e-6 * v_scale);
  std::printf("max |Δw| / max|w| = %.3g, max |Δv| / max|v| = %.3g\n", worst_w / w_scale, worst_v / v_scale);
}

}  // namespace
}  // namespace shockfield::granular
