// Liu et al. (2025) Figs. 3-4 on the 1D impact bar (slow studies, label "slow"): the 30 m/s profiles with
// and without the Riemann correction, and the 300 m/s wave-front width against ΔX and δ.
// Profiles go to $SHOCKFIELD_PD_OUT (default /tmp/shockfield_pd) for docs/theory/pd_plot.py.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "unit/pd/bar_helpers.hpp"

using namespace shockfield;
using namespace shockfield::pd;
using shockfield::pd::testing::Bar;

namespace {

std::filesystem::path out_dir() {
  const char* env = std::getenv("SHOCKFIELD_PD_OUT");
  std::filesystem::path dir = env ? env : "/tmp/shockfield_pd";
  std::filesystem::create_directories(dir);
  return dir;
}

void write_profile(const Bar& bar, const std::string& name) {
  std::ofstream out(out_dir() / name);
  out << "x_m,axial_compression_Pa,velocity_m_s\n";
  const auto x = bar.x();
  const auto s = bar.axial_compression();
  for (std::size_t i = 0; i < x.size(); ++i) out << x[i] << ',' << s[i] << ',' << bar.sim->velocities()[i][0] << '\n';
}

// Front width (10%-90% of the plastic jump) at t = 1.5 µs, 300 m/s.
double plastic_width(double spacing, double m) {
  const double length = 0.024;
  Bar bar(static_cast<int>(length / spacing), spacing, m, 300.0, {true, 0.0});
  bar.run_until(1.5e-6, 0.5 * bar.sim->stable_step());
  write_profile(bar, fmt::format("elastic_plastic_dx{:.0f}um_m{:.0f}.csv", spacing * 1e6, m));
  // Plastic jump from the HEL (541.63 MPa) to 2.27 GPa: widths of 10%-90% between them.
  const auto x = bar.x();
  const auto s = bar.axial_compression();
  const double hel = 541.63e6, top = 2.269e9;
  return std::abs(front_position(x, s, hel + 0.1 * (top - hel)) - front_position(x, s, hel + 0.9 * (top - hel)));
}

}  // namespace

TEST(PdBarSlow, ElasticProfilesWithAndWithoutRiemann) {
  for (bool riemann : {true, false}) {
    Bar bar(1200, 1e-5, 3.0, 30.0, {riemann, 0.0});
    bar.run_until(7.5e-7, 0.5 * bar.sim->stable_step());
    write_profile(bar, riemann ? "elastic_30_riemann.csv" : "elastic_30_plain.csv");
  }
}

// Fig. 4: the front narrows as ΔX shrinks (δ = 3ΔX) and as δ shrinks (ΔX = 10 µm), and δ = ΔX
// is the narrowest (the local limit).
TEST(PdBarSlow, FrontWidthShrinksWithSpacingAndHorizon) {
  const double w20 = plastic_width(20e-6, 3.0), w10 = plastic_width(10e-6, 3.0), w5 = plastic_width(5e-6, 3.0);
  EXPECT_LT(w10, w20);
  EXPECT_LT(w5, w10);
  const double m1 = plastic_width(10e-6, 1.0), m2 = plastic_width(10e-6, 2.0), m4 = plastic_width(10e-6, 4.0);
  EXPECT_LT(m1, m2);
  EXPECT_LT(m2, w10);
  EXPECT_LT(w10, m4);
  std::ofstream(out_dir() / "front_widths.csv") << "dx_um,m,width_um\n20,3," << w20 * 1e6 << "\n10,3," << w10 * 1e6
                                                 << "\n5,3," << w5 * 1e6 << "\n10,1," << m1 * 1e6 << "\n10,2,"
                                                 << m2 * 1e6 << "\n10,4," << m4 * 1e6 << "\n";
}
