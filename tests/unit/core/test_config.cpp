// Case-file validation: every failure names the file, key and line; defaults are recorded.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"

using shockfield::Config;
using shockfield::InputError;
using shockfield::Range;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Config, ReadsTypedValuesAndRecordsDefaults) {
  const Config c = Config::parse("a = 1.5\nb = 3\n[t]\ns = \"x\"\n", "case.toml");
  EXPECT_DOUBLE_EQ(c.get_double("a"), 1.5);
  EXPECT_EQ(c.get_int("b"), 3);
  EXPECT_DOUBLE_EQ(c.get_double_or("missing", 2.25), 2.25);
  EXPECT_EQ(c.table("t").get_string("s"), "x");
  c.check_unknown_keys();
  const std::string resolved = c.resolved_toml();
  EXPECT_NE(resolved.find("missing = 2.25"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("s = 'x'"), std::string::npos) << resolved;
}

TEST(Config, AnInfiniteDefaultIsLeftOutOfTheResolvedConfigSoItReplays) {
  const Config c = Config::parse("[region]\nxhi = 5.0\n");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(c.table("region").get_double_or("xlo", -inf), -inf);
  EXPECT_DOUBLE_EQ(c.table("region").get_double_or("xhi", inf), 5.0);
  c.check_unknown_keys();
  const std::string resolved = c.resolved_toml();
  EXPECT_EQ(resolved.find("xlo"), std::string::npos) << resolved;
  const Config replay = Config::parse(resolved);
  EXPECT_EQ(replay.table("region").get_double_or("xlo", -inf), -inf);
  EXPECT_DOUBLE_EQ(replay.table("region").get_double_or("xhi", inf), 5.0);
}

TEST(Config, IntegerAcceptedWhereANumberIsExpected) {
  const Config c = Config::parse("a = 2\n");
  EXPECT_DOUBLE_EQ(c.get_double("a"), 2.0);
}

TEST(Config, UnknownKeysAreListedWithTheirLines) {
  const Config c = Config::parse("good = 1\ntypo = 2\n[sec]\nx = 1\nmore = 3\n", "case.toml");
  c.get_int("good");
  c.table("sec").get_int("x");
  const std::string msg = error_of([&] { c.check_unknown_keys(); });
  EXPECT_NE(msg.find("case.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'typo' (line 2)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'sec.more' (line 5)"), std::string::npos) << msg;
}

TEST(Config, WrongTypeMissingAndOutOfRangeNameFileKeyAndLine) {
  const Config c = Config::parse("[md]\ntimestep = \"fast\"\nskin = -1.0\n", "case.toml");
  const Config md = c.table("md");
  const std::string type = error_of([&] { md.get_double("timestep"); });
  EXPECT_NE(type.find("case.toml:2: key 'md.timestep': expected a number"), std::string::npos) << type;
  const std::string range = error_of([&] { md.get_double("skin", Range::positive()); });
  EXPECT_NE(range.find("case.toml:3: key 'md.skin': expected a number > 0, got -1"), std::string::npos) << range;
  const std::string missing = error_of([&] { md.get_int("steps"); });
  EXPECT_NE(missing.find("key 'md.steps': missing required value"), std::string::npos) << missing;
}

TEST(Config, ChoicesListTheAllowedValues) {
  const Config c = Config::parse("ensemble = \"npe\"\n", "case.toml");
  const std::string msg = error_of([&] { c.get_choice("ensemble", {"nve", "nvt"}); });
  EXPECT_NE(msg.find("expected one of \"nve\", \"nvt\", got \"npe\""), std::string::npos) << msg;
}

TEST(Config, ArraysOfTablesAreAddressedByIndex) {
  const Config c = Config::parse("[[stage]]\nsteps = 1\n[[stage]]\nsteps = 2\nbad = 0\n", "case.toml");
  const auto stages = c.tables("stage");
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[1].get_int("steps"), 2);
  stages[0].get_int("steps");
  const std::string msg = error_of([&] { c.check_unknown_keys(); });
  EXPECT_NE(msg.find("'stage[1].bad' (line 5)"), std::string::npos) << msg;
}

TEST(Config, SyntaxErrorsGiveLineAndColumn) {
  const std::string msg = error_of([] { Config::parse("a = = 1\n", "case.toml"); });
  EXPECT_NE(msg.find("case.toml:1:"), std::string::npos) << msg;
}

TEST(Config, NonFiniteNumbersAreRejected) {
  const Config c = Config::parse("a = nan\n", "case.toml");
  EXPECT_THROW(c.get_double("a"), InputError);
}

TEST(Range, DescribesItself) {
  EXPECT_EQ(Range::positive().describe(), "> 0");
  EXPECT_EQ(Range::closed(1, 2).describe(), "in [1, 2]");
  EXPECT_FALSE(Range::positive().contains(0.0));
  EXPECT_TRUE(Range::non_negative().contains(0.0));
}

// Issue 14: +-inf passed the default Range although it reads "a finite number"; integers near
// 2^63 were compared after rounding to double.
TEST(Range, NonFiniteNumbersAreOutsideEveryRange) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const Range& r : {Range{}, Range::positive(), Range::non_negative()}) {
    EXPECT_FALSE(r.contains(inf)) << r.describe();
    EXPECT_FALSE(r.contains(-inf)) << r.describe();
    EXPECT_FALSE(r.contains(std::numeric_limits<double>::quiet_NaN())) << r.describe();
  }
  EXPECT_TRUE(Range{}.contains(1e300));
  const Config c = Config::parse("a = inf\nb = -inf\nc = nan\n", "case.toml");
  for (const char* key : {"a", "b", "c"})
    EXPECT_NE(error_of([&] { c.get_double(key); }).find("case.toml:"), std::string::npos) << key;
}

TEST(Range, IntegersAreComparedExactly) {
  // 9223372036854775807 rounds to 9.223372036854775808e18 as a double, which equals the bound.
  const Range r = Range::closed(0, 9223372036854775808.0 - 2048.0);  // the double below 2^63
  EXPECT_FALSE(r.contains(9223372036854775807LL));
  EXPECT_TRUE(r.contains(9223372036854773760LL));  // the bound itself
  const Config c = Config::parse("n = 9223372036854775807\n", "case.toml");
  EXPECT_NE(error_of([&] { c.get_int("n", Range::closed(0, 1e12)); }).find("case.toml:1: key 'n'"),
            std::string::npos);
  EXPECT_NE(error_of([] { Config::parse("n = 99999999999999999999\n", "case.toml"); }).find("case.toml:1"),
            std::string::npos);
}
