// Regions (LAMMPS inside rules, faces included, side out), reading them from a case file,
// delete_atoms and group bits.
#include <gtest/gtest.h>

#include "shockfield/core/error.hpp"
#include "shockfield/md/region.hpp"

namespace shockfield::md {
namespace {

TEST(Region, InsideRulesIncludeTheSurface) {
  const Config c = Config::parse(R"(
    [a]
    shape = "block"
    xlo = 0
    xhi = 1
    ylo = 0
    yhi = 2
    [b]
    shape = "sphere"
    center = [0, 0, 0]
    radius = 1.0
    side = "out"
    [c]
    shape = "cylinder"
    axis = "y"
    center = [1, 1]
    radius = 0.5
    lo = 0
    hi = 3
  )");
  const Region a = region_from_config(c.table("a")), b = region_from_config(c.table("b")),
               cyl = region_from_config(c.table("c"));
  EXPECT_TRUE(a.match(Vec3(1, 2, -1e300)));
  EXPECT_FALSE(a.match(Vec3(1.0000001, 1, 0)));
  EXPECT_FALSE(b.match(Vec3(1, 0, 0)));  // on the sphere: inside, so not matched by side out
  EXPECT_TRUE(b.match(Vec3(1, 0.01, 0)));
  EXPECT_TRUE(cyl.match(Vec3(1.5, 3, 1)));  // x, z around (1, 1); y in [0, 3]
  EXPECT_FALSE(cyl.match(Vec3(1, 3.1, 1)));
  EXPECT_FALSE(cyl.match(Vec3(1, 1, 1.6)));
  c.check_unknown_keys();
}

TEST(Region, BadTablesNameTheKey) {
  const auto error = [](const std::string& toml) {
    try {
      region_from_config(Config::parse(toml, "case.toml"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("shape = \"cone\"").find("case.toml:1: key 'shape'"), std::string::npos);
  EXPECT_NE(error("shape = \"sphere\"\ncenter = [0, 0]\nradius = 1").find("key 'center'"), std::string::npos);
  EXPECT_NE(error("shape = \"sphere\"\ncenter = [0, 0, 0]\nradius = -1").find("key 'radius'"), std::string::npos);
  EXPECT_NE(error("shape = \"block\"\nylo = 1\nyhi = 0").find("case.toml:3: key 'yhi'"), std::string::npos);
  EXPECT_NE(error("shape = \"block\"\nside = \"inside\"").find("key 'side'"), std::string::npos);
}

TEST(Region, DeleteAndGroups) {
  Atoms atoms;
  atoms.mass = {1.0, 1.0};
  for (int i = 0; i < 10; ++i) atoms.add(Vec3(i, 0, 0), i % 2, i + 1);
  Region r;
  r.lo.x() = 2.5;
  r.hi.x() = 5;
  EXPECT_EQ(delete_atoms(r, atoms), 3u);  // x = 3, 4, 5
  EXPECT_EQ(atoms.id, (std::vector<std::int64_t>{1, 2, 3, 7, 8, 9, 10}));
  GroupTable groups;
  const auto left = groups.bit("left");
  EXPECT_EQ(left, 2u);
  r.lo.x() = -1;
  EXPECT_EQ(add_to_group(left, r, atoms), 3u);
  EXPECT_EQ(add_to_group(left, std::vector<int>{1}, atoms), 5u);  // union, as LAMMPS group
  EXPECT_EQ(groups.find("left"), left);
  EXPECT_EQ(groups.bit("left"), left);
  EXPECT_THROW(groups.find("right"), InputError);
  for (int g = 2; g < 32; ++g) groups.bit(std::string("g").append(std::to_string(g)));
  EXPECT_THROW(groups.bit("one_too_many"), InputError);
}

}  // namespace
}  // namespace shockfield::md
