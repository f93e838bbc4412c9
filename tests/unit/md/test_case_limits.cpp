// MD case limits (issue 14): steps = 2^63 - 1 made total_steps overflow to a negative count.
#include <gtest/gtest.h>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/md/case_file.hpp"

namespace shockfield::md {
namespace {

std::string error_of(const std::string& stages) {
  try {
    read_md_case(Config::parse("[md]\n" + stages, "steps.toml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MdCaseLimits, StepCountsAreBoundedSoTheirSumCannotOverflow) {
  std::string e = error_of("[[stage]]\nsteps = 9223372036854775807\n");
  EXPECT_NE(e.find("steps.toml:3: key 'stage[0].steps'"), std::string::npos) << e;
  e = error_of("[[stage]]\nsteps = 600000000000\n[[stage]]\nsteps = 600000000000\n");
  EXPECT_NE(e.find("steps.toml:5: key 'stage[1].steps': the stages up to this one add up to 1200000000000"),
            std::string::npos) << e;
  EXPECT_EQ(error_of("[[stage]]\nsteps = 1000000000000\n"), "");
}

}  // namespace
}  // namespace shockfield::md
