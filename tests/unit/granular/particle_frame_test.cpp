// The granular particle frame (RunOutputs::grain_frame): the chain along z with the simulation's
// values, and its LAMMPS dump (io/particle_frame) read back by shockfield's dump reader to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/outputs.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/io/particle_frame.hpp"

namespace shockfield::granular {
namespace {

Simulation struck_column(std::vector<int>& types) {
  ChainSpec s;
  s.grains = 50;
  s.radius = 2e-3;
  s.gravity = 9.81;
  s.wall = WallKind::rigid;
  Impurity light;
  light.index = 20;
  light.mass_ratio = 0.25;
  s.impurities.push_back(light);
  types.assign(50, 1);
  types[20] = 2;
  Simulation sim(build_chain(s), Impulse{Impulse::Kind::velocity, 0.1, 2, {}, {}});
  for (int k = 0; k < 400; ++k) sim.step();
  return sim;
}

TEST(GranularParticleFrame, IsTheChainAlongZWithTheSimulationsValues) {
  std::vector<int> types;
  const Simulation sim = struck_column(types);
  const io::ParticleFrame f = RunOutputs::grain_frame(sim, types);
  ASSERT_EQ(f.size(), 50u);
  EXPECT_EQ(f.step, 400);
  EXPECT_EQ(f.time, sim.time());
  ASSERT_EQ(f.arrays.size(), 8u);
  const auto array = [&](const std::string& name) -> const io::VtkArray& {
    for (const auto& a : f.arrays)
      if (a.name == name) return a;
    throw std::runtime_error("no array " + name);
  };
  double moved = 0;
  for (std::size_t i = 0; i < 50; ++i) {
    // Depth and "+ down" turned over into z up; exact, a sign change only.
    EXPECT_EQ(f.xyz[3 * i], 0.0);
    EXPECT_EQ(f.xyz[3 * i + 2], -sim.position(i));
    EXPECT_EQ(array("velocity").values[3 * i + 2], -sim.velocity()[i]);
    EXPECT_EQ(array("force").values[3 * i + 2], -sim.force()[i]);
    EXPECT_EQ(array("displacement").values[3 * i + 2], -sim.displacement()[i]);
    EXPECT_EQ(array("grain").values[i], static_cast<double>(i));
    moved = std::max(moved, std::abs(sim.velocity()[i]));
  }
  EXPECT_GT(moved, 0.01);  // the pulse is in the chain: the values compared are not all zero
  EXPECT_EQ(array("contact_force").values[10], sim.contact_force()[10]);
  EXPECT_EQ(array("overlap").values[10], sim.overlap(10));
  EXPECT_EQ(array("overlap").values[49], sim.wall_overlap());  // the last grain's contact: the wall
  EXPECT_TRUE(array("grain").integer);
  EXPECT_EQ(f.type[20], 2);
}

TEST(GranularParticleFrame, DumpReadsBackBitForBitWithLammpsNames) {
  std::vector<int> types;
  const Simulation sim = struck_column(types);
  const io::ParticleFrame f = RunOutputs::grain_frame(sim, types);
  std::stringstream text;
  io::write_dump_frame(text, io::particle_dump_frame(f), io::DumpWriteOptions{true});
  const auto frames = io::read_dump(text, "grains.lammpstrj");
  ASSERT_EQ(frames.size(), 1u);
  const io::DumpFrame& d = frames[0];
  EXPECT_EQ(d.timestep, 400);
  ASSERT_TRUE(d.time.has_value());
  EXPECT_EQ(*d.time, sim.time());  // shortest round-trip text: the same double
  EXPECT_EQ(d.units, "si");
  const std::vector<std::string> columns{"id", "type", "x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz",
                                         "displacement_x", "displacement_y", "displacement_z", "contact_force",
                                         "overlap", "radius", "mass", "grain"};
  EXPECT_EQ(d.columns, columns);
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(d.column("id")[i], static_cast<double>(i + 1));
    EXPECT_EQ(d.column("type")[i], types[i]);
    EXPECT_EQ(d.column("z")[i], f.xyz[3 * i + 2]);
    EXPECT_EQ(d.column("vz")[i], -sim.velocity()[i]);
    EXPECT_EQ(d.column("fz")[i], -sim.force()[i]);
    EXPECT_EQ(d.column("overlap")[i], f.arrays[4].values[i]);
    EXPECT_EQ(d.column("mass")[i], sim.chain().mass[i]);
    // The box holds every grain whole (free bodies: shrink-wrapped bounds).
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(d.box.lo[a], f.xyz[3 * i + a] - 2e-3 * (1 - 1e-12));
      EXPECT_GE(d.box.hi[a], f.xyz[3 * i + a] + 2e-3 * (1 - 1e-12));
    }
  }
  EXPECT_EQ(d.bounds[2], "ss");
}

TEST(ParticleDumpFrame, RefusesAnArrayADumpCannotHold) {
  io::ParticleFrame f{0, 0.0, {0, 0, 0}, {}, 0.0, {{"odd", 2, {1, 2}, "1"}}};
  EXPECT_THROW(io::particle_dump_frame(f), InputError);
}

}  // namespace
}  // namespace shockfield::granular
