// The case diff behind --resume: changed, added and removed values by dotted key (arrays of tables
// by index), 10 == 10.0, [derived]/[provenance] ignored; key patterns with '*' per segment.
#include <gtest/gtest.h>

#include "shockfield/core/case_diff.hpp"
#include "shockfield/core/error.hpp"

using namespace shockfield;

namespace {

const char* kBefore = R"(
method = "md"
end_time = 10
[output]
dump_interval = 100
fields = ["x", "v"]
[[stage]]
steps = 1000
[[stage]]
steps = 2000
[stage.piston]
speed = 1.5
[derived]
atoms = 100
)";

}  // namespace

TEST(CaseDiff, IdenticalCasesHaveNoChanges) {
  EXPECT_TRUE(diff_cases(kBefore, kBefore).empty());
  // Same values written differently: 10 vs 10.0, another order, other [derived]/[provenance].
  const char* same = R"(
end_time = 10.0
method = 'md'
[[stage]]
steps = 1000
[[stage]]
steps = 2000
piston = { speed = 1.5 }
[output]
fields = [ "x", "v" ]
dump_interval = 100
[derived]
atoms = 999
[provenance]
host = "elsewhere"
)";
  EXPECT_TRUE(diff_cases(kBefore, same).empty());
}

TEST(CaseDiff, ChangedAddedAndRemovedValuesSortedByKey) {
  const char* after = R"(
method = "md"
end_time = 20
[output]
dump_interval = 100
fields = ["x"]
thermo_every = 10
[[stage]]
steps = 1000
[[stage]]
steps = 2000
[stage.piston]
speed = 2.0
)";
  const auto changes = diff_cases(kBefore, after);
  ASSERT_EQ(changes.size(), 4u);
  EXPECT_EQ(changes[0].key, "end_time");
  EXPECT_EQ(changes[0].before, "10");
  EXPECT_EQ(changes[0].after, "20");
  EXPECT_EQ(changes[1].key, "output.fields");
  EXPECT_EQ(changes[1].before, "[ 'x', 'v' ]");
  EXPECT_EQ(changes[1].after, "[ 'x' ]");
  EXPECT_EQ(changes[2].key, "output.thermo_every");
  EXPECT_EQ(changes[2].before, "(absent)");
  EXPECT_EQ(changes[2].after, "10");
  EXPECT_EQ(changes[3].key, "stage[1].piston.speed");
  EXPECT_EQ(changes[3].before, "1.5");
  EXPECT_EQ(changes[3].after, "2.0");
}

TEST(CaseDiff, RemovedStageListsItsValuesAsAbsent) {
  const auto changes = diff_cases("[[stage]]\nsteps = 1\n[[stage]]\nsteps = 2\n", "[[stage]]\nsteps = 1\n");
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].key, "stage[1].steps");
  EXPECT_EQ(changes[0].before, "2");
  EXPECT_EQ(changes[0].after, "(absent)");
}

TEST(CaseDiff, BadTomlSaysWhichCase) {
  try {
    diff_cases("a = 1\n", "a = = 1\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the case given to --resume:1:"), std::string::npos) << e.what();
  }
  // The stored case is named by where it came from (a damaged stored case, found by the resume_case
  // fuzz target when it was a file beside the checkpoint: the message named no file).
  try {
    diff_cases("[a\n", "a = 1\n", "run/checkpoint.h5 (its case_input)");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run/checkpoint.h5 (its case_input):1:"), std::string::npos) << e.what();
  }
}

TEST(CaseDiff, KeyPatternsMatchSegmentBySegment) {
  EXPECT_TRUE(key_matches("end_time", "end_time"));
  EXPECT_FALSE(key_matches("end_time", "end"));
  EXPECT_TRUE(key_matches("output.dump_interval", "output.*_interval"));
  EXPECT_TRUE(key_matches("output._interval", "output.*_interval"));
  EXPECT_FALSE(key_matches("output.dump_intervals", "output.*_interval"));
  EXPECT_FALSE(key_matches("output.a.b_interval", "output.*_interval"));  // '*' stays in its segment
  EXPECT_TRUE(key_matches("stage[1].steps", "stage.*.steps"));
  EXPECT_TRUE(key_matches("stage[12].steps", "stage[*].steps"));
  EXPECT_FALSE(key_matches("stage[1].piston.speed", "stage.*.steps"));
  EXPECT_TRUE(key_matches("stage[1].piston.speed", "stage.*.*.*"));
  EXPECT_TRUE(key_matches("a.xyzxyz", "a.*xyz"));  // backtracking past an early partial match
  EXPECT_FALSE(key_matches("a.xyzxy", "a.*xyz"));
  EXPECT_TRUE(key_matches("thermo_every", "*"));
  EXPECT_FALSE(key_matches("output.thermo_every", "*"));
}
