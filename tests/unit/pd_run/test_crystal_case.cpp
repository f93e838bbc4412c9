// model = "crystal" case files: grains of a polycrystal, the single crystal's Schmid factors,
// Taylor grains per point, and stopped and resumed crystal runs (slab grains, Taylor grains) that
// write the same profiles bitwise (the crystal state goes through the checkpoint).
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "shockfield/core/error.hpp"
#include "shockfield/pd/case_file.hpp"
#include "shockfield/pd/run_case.hpp"

using namespace shockfield;
using namespace shockfield::pd;

namespace {

const char* kCase = R"(method = "pd"
[body]
dim = 1
counts = [120]
spacing = 10e-6
[material]
model = "crystal"
density = 8960.0
orientation = "random_grains"
grain_planes = [8, 12]
seed = 5
[solver]
end_time = 8e-8
[loading]
speed = 100.0
[output]
profile_interval = 4e-8
)";

std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(PdCrystalCase, GrainsOfEightToTwelvePlanes) {
  const Config root = Config::parse(kCase);
  root.get_choice("method", {"pd"});
  const PdCase c = read_pd_case(root);
  const auto& spec = std::get<CrystalSpec>(c.material);
  ASSERT_TRUE(spec.polycrystal);
  const CrystalBody body = crystal_body(spec, lattice_cloud(1, c.body.counts, c.body.spacing));
  std::map<int, int> size;
  for (int g : body.grain) ++size[g];
  EXPECT_EQ(static_cast<int>(size.size()), body.grains);
  for (const auto& [g, n] : size) {
    if (g + 1 == body.grains) continue;  // the last grain is cut by the body's end
    EXPECT_TRUE(n >= 8 && n <= 12) << "grain " << g << " has " << n << " points";
  }
  EXPECT_NE(body.materials[0].aggregate.orientations[0], body.materials[119].aggregate.orientations[0]);
}

TEST(PdCrystalCase, SchmidFactorsOfHundredAndHundredEleven) {
  CrystalMaterial m;
  m.aggregate.orientations = {materials::rotation_loading_along(Vec3(1, 0, 0))};
  EXPECT_NEAR(schmid_factor_along_x(m), 1.0 / std::sqrt(6.0), 1e-12);
  m.aggregate.orientations = {materials::rotation_loading_along(Vec3(1, 1, 1))};
  EXPECT_NEAR(schmid_factor_along_x(m), std::sqrt(6.0) / 9.0, 1e-12);
}

namespace {

// Stops `text` after 17 steps, resumes it and compares the output with an uninterrupted run.
void expect_bitwise_resume(const std::string& text, const std::string& name) {
  const auto dir = shockfield::testing::scratch_path("shockfield_pd_crystal_resume_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.toml") << text;
  auto run = [&](const std::string& out, long long stop_after, bool resume) {
    RunOptions o;
    o.case_file = dir / "case.toml";
    o.output = dir / out;
    o.quiet = true;
    o.stop_after = stop_after;
    o.resume = resume;
    const Config root = Config::load(o.case_file);
    root.get_choice("method", {"pd"});
    run_case(root, o);
  };
  run("straight", 0, false);
  EXPECT_THROW(run("split", 17, false), StopRequested);
  run("split", 0, true);
  for (const char* f : {"series.csv", "profiles/profile_1.csv", "profiles/profile_2.csv", "profiles/index.csv"})
    EXPECT_EQ(slurp(dir / "straight" / f), slurp(dir / "split" / f)) << name << ": " << f;
}

}  // namespace

TEST(PdCrystalCase, StoppedAndResumedRunIsBitwiseIdentical) { expect_bitwise_resume(kCase, "slabs"); }

// Every point's grains go through the checkpoint (N_g grain states per point).
TEST(PdCrystalCase, StoppedAndResumedTaylorRunIsBitwiseIdentical) {
  std::string text = kCase;
  const std::string slabs = "orientation = \"random_grains\"\ngrain_planes = [8, 12]\n";
  text.replace(text.find(slabs), slabs.size(), "orientation = \"random\"\ntaylor_grains = 3\n");
  expect_bitwise_resume(text, "taylor");
}

// taylor_grains: N_g copies of a direction, or N_g random orientations shared by every point.
TEST(PdCrystalCase, TaylorGrainsPerPoint) {
  auto spec_of = [](const std::string& orientation) {
    std::string text = kCase;
    const std::string slabs = "orientation = \"random_grains\"\ngrain_planes = [8, 12]\nseed = 5\n";
    text.replace(text.find(slabs), slabs.size(), orientation);
    const Config root = Config::parse(text);
    root.get_choice("method", {"pd"});
    const PdCase c = read_pd_case(root);
    root.check_unknown_keys();
    return std::get<CrystalSpec>(c.material);
  };
  const CrystalSpec copies = spec_of("direction = [1.0, 1.0, 1.0]\ntaylor_grains = 3\n");
  ASSERT_EQ(copies.base.aggregate.orientations.size(), 3u);
  for (const Mat3& g : copies.base.aggregate.orientations)
    EXPECT_EQ(g, materials::rotation_loading_along(Vec3(1, 1, 1)));
  const CrystalSpec random = spec_of("orientation = \"random\"\ntaylor_grains = 4\n");
  EXPECT_FALSE(random.polycrystal);
  ASSERT_EQ(random.base.aggregate.orientations.size(), 4u);
  EXPECT_NE(random.base.aggregate.orientations[0], random.base.aggregate.orientations[1]);
  const CrystalBody body = crystal_body(random, lattice_cloud(1, {120, 1, 1}, 10e-6));
  EXPECT_EQ(body.materials.size(), 1u);  // one aggregate shared by every point
  EXPECT_THROW(spec_of("orientation = \"random_grains\"\ngrain_planes = [8, 12]\ntaylor_grains = 2\n"), InputError);
}
