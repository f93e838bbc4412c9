// A run stopped as by Ctrl-C and resumed from its checkpoint writes the same series and fields as
// the uninterrupted run, bitwise (same threads); the uninterrupted run does not depend on the
// thread count.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/mpm/run_case.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

std::string slurp(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void run(const fs::path& case_file, const fs::path& out, long long stop_after = 0, bool resume = false) {
  RunOptions o;
  o.case_file = case_file;
  o.output = out;
  o.quiet = true;
  o.stop_after = stop_after;
  o.resume = resume;
  o.overwrite = !resume;
  const Config root = Config::load(case_file);
  root.get_string("method");  // read by `shockfield run`
  mpm::run_case(root, o);
}

TEST(MpmRestart, ResumeIsBitwiseAndThreadIndependent) {
  const fs::path dir = shockfield::testing::scratch_path("shockfield_mpm_restart_test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path case_file = "cli/cases/mpm_tiny.toml";
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  run(case_file, dir / "straight");
  EXPECT_THROW(run(case_file, dir / "split", 17), StopRequested);
  ASSERT_TRUE(fs::exists(dir / "split" / "checkpoint.h5"));
  run(case_file, dir / "split", 0, true);
  omp_set_num_threads(1);
  run(case_file, dir / "one_thread");
  omp_set_num_threads(threads);

  const std::string series = slurp(dir / "straight" / "series.csv");
  EXPECT_GT(std::count(series.begin(), series.end(), '\n'), 20);
  EXPECT_EQ(series, slurp(dir / "split" / "series.csv"));
  EXPECT_EQ(series, slurp(dir / "one_thread" / "series.csv"));
  for (const char* f : {"grid.pvd", "particles.pvd", "histograms/hist_0.csv"})
    EXPECT_EQ(slurp(dir / "straight" / f), slurp(dir / "split" / f)) << f;
  for (const auto& e : fs::directory_iterator(dir / "straight" / "fields"))
    EXPECT_EQ(slurp(e.path()), slurp(dir / "split" / "fields" / e.path().filename())) << e.path();
  fs::remove_all(dir);
}

}  // namespace
