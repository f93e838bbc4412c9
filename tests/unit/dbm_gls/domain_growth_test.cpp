// The domain-growth speed u_DG (Xu et al. 2015, §4.3, eq. 34): the slope of R(t) over [t_SD, t_SD + window]
// (phase_separation.hpp, domain_growth), and the u_DG column of a GLS run's summary.csv
// (gls_run.hpp, write_phase_summary) on a synthetic series.csv whose slope is known.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "shockfield/dbm/gls_run.hpp"
#include "shockfield/dbm/phase_separation.hpp"
#include "support/scratch_path.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

constexpr double kTsd = 0.46, kSpeed = 0.04, kWindow = 0.5;

// Samples every 0.02 to t_last: D peaks at t_SD; R falls before it, rises at kSpeed over
// [t_SD, t_SD + kWindow], then stays flat (the late, box-limited stage a longer window would average in).
std::vector<PhaseSample> synthetic_run(double t_last) {
  std::vector<PhaseSample> samples;
  for (int k = 0; 0.02 * k <= t_last + 1e-12; ++k) {
    PhaseSample s;
    s.t = 0.02 * k;
    s.D = std::exp(-(s.t - kTsd) * (s.t - kTsd));
    s.D_force = 0.1 * s.D;
    s.boundary_length = 3.0 - std::abs(s.t - 0.44);
    s.domain_size = 0.1 + (s.t < kTsd ? 0.2 * (kTsd - s.t) : kSpeed * std::min(s.t - kTsd, kWindow));
    samples.push_back(s);
  }
  return samples;
}

}  // namespace

TEST(DbmDomainGrowth, SlopeOverTheEarlyWindowIsTheKnownSpeed) {
  const std::vector<PhaseSample> run = synthetic_run(4.0);
  const DomainGrowth g = domain_growth(run, kTsd, kWindow);
  EXPECT_NEAR(g.speed, kSpeed, 1e-12);
  EXPECT_NEAR(g.t_begin, kTsd, 1e-12);
  EXPECT_NEAR(g.t_end, kTsd + kWindow, 1e-12);
  // The former definition, the slope over [t_SD, t_end] of the run, averages the plateau in: < half.
  EXPECT_LT(domain_growth(run, kTsd, 4.0).speed, 0.5 * kSpeed);
  // A run that ends inside the window: the window stops at its last sample, the slope is still the speed.
  const DomainGrowth cut = domain_growth(synthetic_run(0.7), kTsd, kWindow);
  EXPECT_NEAR(cut.t_end, 0.7, 1e-12);
  EXPECT_NEAR(cut.speed, kSpeed, 1e-12);
  // Fewer than 3 samples in the window: no slope.
  EXPECT_TRUE(std::isnan(domain_growth(synthetic_run(0.48), kTsd, kWindow).speed));
}

TEST(DbmDomainGrowth, SummaryColumnIsTheWindowsSlope) {
  // series.csv with the columns write_phase_summary reads (time, D, D_force, L, R) and one it does not.
  const auto folder = shockfield::testing::scratch_path("domain_growth_summary");
  std::filesystem::create_directories(folder);
  const std::vector<PhaseSample> run = synthetic_run(4.0);
  {
    std::ofstream series(folder / "series.csv");
    series << "step,time,D,D_force,rho_min,L,R\n";
    series.precision(10);  // the digits io::CsvWriter writes
    for (std::size_t k = 0; k < run.size(); ++k)
      series << k << ',' << run[k].t << ',' << run[k].D << ',' << run[k].D_force << ",0.5," << run[k].boundary_length
             << ',' << run[k].domain_size << '\n';
  }
  const auto summary_row = [&](double window) {
    GlsCaseSpec spec;
    spec.growth_window = window;
    Logger quiet(folder / "log.txt", false, false);
    write_phase_summary(folder, spec, quiet);
    std::ifstream in(folder / "summary.csv");
    std::string header, row;
    std::getline(in, header), std::getline(in, row);
    EXPECT_EQ(header, "t_SD,D_max,R_SD,t_SD_force,D_force_max,t_L_max,L_max,u_DG,t_DG_begin,t_DG_end");
    std::vector<double> values;
    for (std::size_t at = 0, next; at <= row.size(); at = next + 1) {
      next = std::min(row.find(',', at), row.size());
      values.push_back(std::stod(row.substr(at, next - at)));
    }
    return values;
  };
  const std::vector<double> early = summary_row(kWindow);
  ASSERT_EQ(early.size(), 10u);
  EXPECT_NEAR(early[0], kTsd, 1e-9);                        // t_SD, the peak of D
  EXPECT_NEAR(early[2], 0.1, 1e-9);                         // R_SD = R(t_SD)
  EXPECT_NEAR(early[7], kSpeed, 1e-8);                      // u_DG (10 written digits)
  EXPECT_NEAR(early[8], kTsd, 1e-9);                        // the window written beside it
  EXPECT_NEAR(early[9], kTsd + kWindow, 1e-9);
  const std::vector<double> late = summary_row(2.0);        // the column follows growth_window
  EXPECT_NEAR(late[7], domain_growth(run, kTsd, 2.0).speed, 1e-8);
  EXPECT_LT(late[7], 0.8 * kSpeed);
  std::filesystem::remove_all(folder);
}
