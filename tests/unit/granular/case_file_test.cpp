// The granular case reader (every key read, bad input refused with file and key before the
// run), the checkpoint round trip (a resumed run continues bitwise) and the scheduled outputs.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/case_file.hpp"
#include "shockfield/granular/checkpoint.hpp"
#include "shockfield/granular/outputs.hpp"

namespace shockfield::granular {
namespace {

const std::string kColumn = R"(
method = "granular"
[chain]
grains = 200
radius = 2e-3
density = 7850
youngs_modulus = 200e9
poisson_ratio = 0.3
gravity = 9.81
damping = 1e-3
[wall]
kind = "elastic"
youngs_modulus = 70e9
poisson_ratio = 0.33
[impulse]
kind = "velocity"
velocity = 0.05
grains = 2
[[impurity]]
index = 100
mass_ratio = 0.25
[run]
end_time = 1e-4
[output]
series_interval = 1e-5
energy_above = [95, 200]
probes = [0, 100, 199]
probe_interval = 2e-6
field_interval = 1e-5
spacetime_stride = 10
signal_interval = 1e-5
)";

Config with(const std::string& text) { return Config::parse(text, "case.toml"); }

// The message of the InputError that reading `text` throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    const Config root = with(text);
    root.get_choice("method", {"granular"});
    read_granular_case(root);
    root.check_unknown_keys();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(GranularCase, ReadsEveryKeyAndDerivesTheStep) {
  const Config root = with(kColumn);
  root.get_choice("method", {"granular"});
  const GranularCase c = read_granular_case(root);
  EXPECT_NO_THROW(root.check_unknown_keys());
  EXPECT_EQ(c.chain.grains, 200);
  EXPECT_EQ(c.chain.wall, WallKind::elastic);
  ASSERT_EQ(c.chain.impurities.size(), 1u);
  EXPECT_DOUBLE_EQ(c.chain.impurities[0].mass_ratio, 0.25);
  EXPECT_FALSE(c.chain.impurities[0].poisson_ratio.has_value());
  const Config own = with(replace(kColumn, "mass_ratio = 0.25", "mass_ratio = 0.25\npoisson_ratio = 0.21\nmodulus_ratio = 0.5"));
  own.get_choice("method", {"granular"});
  const GranularCase c_own = read_granular_case(own);
  EXPECT_DOUBLE_EQ(c_own.chain.impurities[0].poisson_ratio.value(), 0.21);
  EXPECT_DOUBLE_EQ(c_own.chain.impurities[0].modulus_ratio, 0.5);
  EXPECT_EQ(c.impulse.grains, 2);
  EXPECT_EQ(c.output.probes.size(), 3u);
  EXPECT_GT(c.run.stable_step, 0.0);
  EXPECT_NE(root.resolved_toml().find("stable_step"), std::string::npos);
  const Simulation sim = build_simulation(c);
  EXPECT_DOUBLE_EQ(sim.time_step(), 0.05 * c.run.stable_step);
}

TEST(GranularCase, RefusesBadInputNamingFileAndKey) {
  struct Bad {
    const char* from;
    const char* to;
    const char* said;  ///< a part of the message
  };
  const Bad cases[] = {
      {"radius = 2e-3", "radius = -1e-3", "case.toml"},
      {"radius = 2e-3", "radius = 0", "chain.radius"},
      {"gravity = 9.81", "gravity = 0\ngap = -1e-7", "overlapping"},
      {"end_time = 1e-4", "end_time = 1e-4\ntime_step = 1e-3", "run.time_step"},
      {"end_time = 1e-4", "end_time = 1e-4\ntime_step = 1e-3", "stable step"},
      {"index = 100", "index = 200", "impurity"},
      {"kind = \"elastic\"", "kind = \"none\"", "chain.gravity"},
      {"probes = [0, 100, 199]", "probes = [0, 200]", "output.probes"},
      {"energy_above = [95, 200]", "energy_above = [0, 95]", "output.energy_above"},
      {"mass_ratio = 0.25", "mass_ratio = 0.25\npoisson_ratio = 0.5", "impurity[0].poisson_ratio"},
      {"damping = 1e-3", "damping = 1e-3\nstiffness = 2", "chain.stiffness"},
      {"signal_interval = 1e-5", "signal_interval = 1e-5\ndump = true", "output.dump"},
      {"signal_interval = 1e-5", "signal_interval = 1e-5\ndump = true", "profile_interval > 0"},
      {"signal_interval = 1e-5", "signal_interval = 1e-5\nprofile_interval = 1e-10", "output.profile_interval"},
      {"signal_interval = 1e-5", "signal_interval = 1e-5\nprofile_interval = 5e-5\nvtk_encoding = \"gz\"",
       "output.vtk_encoding"},
      {"kind = \"velocity\"\nvelocity = 0.05\ngrains = 2",
       "kind = \"force\"\ntimes = [0, 1e-5, 5e-6]\nforces = [0, 1, 0]", "impulse.times"},
  };
  for (const Bad& bad : cases) {
    const std::string message = error_of(replace(kColumn, bad.from, bad.to));
    EXPECT_NE(message.find(bad.said), std::string::npos) << bad.to << ": " << message;
  }
  EXPECT_EQ(error_of(kColumn), "");
  // probes is optional, as documented.
  EXPECT_EQ(error_of(replace(kColumn, "probes = [0, 100, 199]\n", "")), "");
}

TEST(GranularCase, CheckpointResumeContinuesBitwiseAndOutputsHaveTheirColumns) {
  const auto dir = shockfield::testing::scratch_path("shockfield_granular_ckpt");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const Config root = with(kColumn);
  root.get_choice("method", {"granular"});
  const GranularCase c = read_granular_case(root);
  Simulation straight = build_simulation(c), stopped = build_simulation(c);
  OutputCounters counters;
  std::vector<std::array<double, 2>> expected_above;  ///< excess_energy(0, 95), (0, 200) at each series row
  {
    RunOutputs out(dir, c, stopped, 600);
    for (int s = 0; s < 300; ++s) {
      stopped.step();
      straight.step();
      const auto before = counters.series;
      out.write_due(stopped, counters);
      if (counters.series > before) expected_above.push_back({stopped.excess_energy(0, 95), stopped.excess_energy(0, 200)});
    }
  }
  write_checkpoint(dir / "checkpoint.h5", stopped, counters);
  Simulation resumed = build_simulation(c);
  const OutputCounters back = read_checkpoint(dir / "checkpoint.h5", resumed);
  EXPECT_EQ(back.probes, counters.probes);
  EXPECT_EQ(back.series, counters.series);
  for (int s = 0; s < 300; ++s) {
    straight.step();
    resumed.step();
  }
  // Damped contacts see the half-step velocity: the restored forces make the continuation exact.
  EXPECT_EQ(resumed.displacement(), straight.displacement());
  EXPECT_EQ(resumed.velocity(), straight.velocity());
  EXPECT_EQ(resumed.time(), straight.time());
  std::ifstream probes(dir / "probes.csv");
  std::string header;
  std::getline(probes, header);
  EXPECT_EQ(header.rfind("time_s,velocity_0_m_s,force_0_N,overlap_0_m,velocity_100_m_s", 0), 0u) << header;
  EXPECT_TRUE(std::filesystem::exists(dir / "spacetime_force.csv"));
  // energy_above.csv comes with every series row: Simulation::excess_energy(0, g) at the row's
  // step, and for g = N (the whole chain with its floor) the total of series.csv.
  std::ifstream above(dir / "energy_above.csv"), series(dir / "series.csv");
  std::string line, series_line;
  std::getline(above, line);
  std::getline(series, series_line);
  EXPECT_EQ(line, "time_s,energy_above_95_J,energy_above_200_J");
  std::size_t rows = 0;
  const auto cells = [](const std::string& text) {
    std::vector<double> v;
    std::stringstream in(text);
    for (std::string cell; std::getline(in, cell, ',');) v.push_back(std::stod(cell));
    return v;
  };
  for (; std::getline(above, line) && std::getline(series, series_line); ++rows) {
    const std::vector<double> row = cells(line), thermo = cells(series_line);
    ASSERT_EQ(row.size(), 3u);
    ASSERT_LT(rows, expected_above.size());
    EXPECT_EQ(row[0], thermo[0]);
    EXPECT_NEAR(row[1], expected_above[rows][0], 1e-9 * std::abs(expected_above[rows][0]));
    EXPECT_NEAR(row[2], expected_above[rows][1], 1e-9 * std::abs(expected_above[rows][1]));
    EXPECT_NEAR(row[2], thermo[4], 1e-9 * std::abs(thermo[4]));
  }
  EXPECT_EQ(rows, static_cast<std::size_t>(counters.series));
  EXPECT_TRUE(std::filesystem::exists(dir / "signal.csv"));
  // The summary: damping (γ = 1e-3 N·s/m) removes a little energy, so the error is small but
  // not round-off; the signal is below the top.
  const auto summary = summary_results(resumed, build_simulation(c).thermo().total);
  ASSERT_EQ(summary.size(), 9u);
  EXPECT_EQ(summary[1].first, "steps");
  EXPECT_EQ(summary[1].second, 600.0);
  EXPECT_LT(summary[5].second, 0.1);
  EXPECT_GT(summary[6].second, 0.0);
  // A checkpoint of another chain is refused with the file named.
  const GranularCase other = read_granular_case([&] {
    const Config r = with(replace(kColumn, "grains = 200", "grains = 201"));
    return r;
  }());
  Simulation wrong = build_simulation(other);
  try {
    read_checkpoint(dir / "checkpoint.h5", wrong);
    FAIL() << "a checkpoint of 200 grains was accepted by a chain of 201";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint.h5"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace shockfield::granular

namespace shockfield::granular {
namespace {

TEST(GranularCase, ExampleCaseFilesAreValid) {
  for (const char* name : {"horizontal_soliton.toml", "column_weak.toml", "column_light_impurity.toml"}) {
    const Config root = Config::load(std::filesystem::path("../examples/granular_chain") / name);
    root.get_choice("method", {"granular"});
    EXPECT_NO_THROW({
      const GranularCase c = read_granular_case(root);
      root.check_unknown_keys();
      build_simulation(c);
    }) << name;
  }
}

}  // namespace
}  // namespace shockfield::granular
