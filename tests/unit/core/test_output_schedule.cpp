// The output schedule is bounded (issue 14): at most one frame per step, however short the
// interval; an interval that would write more than max_series_rows / max_frames by end_time, or
// one shorter than a fixed time step, is refused naming the key and the count.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"

using namespace shockfield;

namespace {

std::string refusal(const std::string& toml, double end_time, double dt = 0) {
  try {
    const Config root = Config::parse(toml, "case.toml");
    const auto output = root.optional_table("output");
    const OutputIntervals s = read_output_intervals(output, end_time, {.profiles = true, .fields = true});
    if (dt > 0) check_intervals_against_step(*output, s, dt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OutputSchedule, WritesAtMostOneFramePerStep) {
  // Interval 1e-3 and steps of 1: frames 0..1000 are due at t = 1, and only frame 0 is written
  // (the old loop wrote 1001 identical frames); the next step at t = 2 writes one more.
  long long count = 0;
  std::vector<long long> written;
  write_due_frames(count, 1e-3, 1.0, [&](long long k) { written.push_back(k); });
  EXPECT_EQ(written, std::vector<long long>{0});
  EXPECT_EQ(count, 1001);
  write_due_frames(count, 1e-3, 2.0, [&](long long k) { written.push_back(k); });
  EXPECT_EQ(written, (std::vector<long long>{0, 1001}));
  EXPECT_EQ(count, 2001);
}

TEST(OutputSchedule, SkipsFarAheadInConstantTime) {
  // A PD case of density 1e303 (fuzzer, seed 7) gave t / interval = 1e140: the skip counted up
  // one frame at a time and never ended. It now lands on the first frame after t at once, and
  // beyond 2^62 frames stops writing.
  long long count = 0;
  int frames = 0;
  write_due_frames(count, 1.0, 1e9, [&](long long) { ++frames; });
  EXPECT_EQ(count, 1000000001);
  write_due_frames(count, 1e-8, 1e132, [&](long long) { ++frames; });
  EXPECT_EQ(count, 4611686018427387904LL);
  write_due_frames(count, 1e-8, 1e132, [&](long long) { ++frames; });
  EXPECT_EQ(frames, 2);
}

TEST(OutputSchedule, RegularStepsWriteEveryFrame) {
  long long count = 0;
  int frames = 0;
  for (int step = 0; step <= 10; ++step) write_due_frames(count, 0.5, 0.5 * step, [&](long long) { ++frames; });
  EXPECT_EQ(frames, 11);
  EXPECT_EQ(count, 11);
}

TEST(OutputSchedule, RefusesUnboundedRowsAndFramesByKeyWithTheCount) {
  EXPECT_EQ(refusal("[output]\nseries_interval = 2e-9\n", 40e-9), "");
  const std::string rows = refusal("[output]\nseries_interval = 2e-9\n", 1e300);  // MPM end_time = 1e300
  EXPECT_NE(rows.find("output.series_interval"), std::string::npos) << rows;
  EXPECT_NE(rows.find("over 1e308 series rows"), std::string::npos) << rows;
  const std::string frames = refusal("[output]\nfield_interval = 1e-300\n", 0.2);  // DBM, one frame forever
  EXPECT_NE(frames.find("output.field_interval"), std::string::npos) << frames;
  EXPECT_NE(frames.find("field frames"), std::string::npos) << frames;
  EXPECT_NE(refusal("[output]\nprofile_interval = 1e-9\n", 1.0).find("output.profile_interval"), std::string::npos);
}

TEST(OutputSchedule, RefusesAnIntervalShorterThanAFixedStep) {
  const std::string m = refusal("[output]\nseries_interval = 1e-5\n", 0.2, 6.25e-4);
  EXPECT_NE(m.find("output.series_interval"), std::string::npos) << m;
  EXPECT_NE(m.find("shorter than the time step"), std::string::npos) << m;
  EXPECT_EQ(refusal("[output]\nseries_interval = 6.25e-4\n", 0.2, 6.25e-4), "");  // one step: fine
}
