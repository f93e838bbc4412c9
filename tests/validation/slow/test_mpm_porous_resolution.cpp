// The paper's porous aluminium case (Xu et al. 2015, §4.1, Fig 19: Δ = 0.029, r = 50 µm, 2 × 5 mm, slip
// wall at 1000 m/s; examples/mpm_porous_al/case.toml) at 20 µm and 10 µm cells (void radius 2.5
// and 5 cells), bottom window [100, 900] µm at 250 ns, beside the paper's 3.14 g/cm³, 16.7 GPa and
// 432 K. Density and pressure: within 2 % and 5 % of the paper at both resolutions (the paper's
// values are read off a figure; a porous body sits below the solid Hugoniot 3.174 g/cm³,
// 18.06 GPa). Temperature: the paper's 432 K is below what its own eq. 7 gives for the solid at this
// shock (≈ 488 K + ~6 K plastic work, examples/mpm_porous_al/README.md), and a porous body
// dissipates more, so the check is T above the solid value; the measured T at both resolutions
// is recorded to show the trend (README table). Label "slow": the 10 µm run is ~4·10⁵ particles
// × ~1100 steps (minutes on 2 cores). ctest --preset release -L slow -R PorousResolution.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/mpm/run_case.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

void replace_line(std::string& text, const std::string& key, const std::string& value) {
  const auto at = text.find("\n" + key + " = ");
  ASSERT_NE(at, std::string::npos) << key;
  const auto end = text.find('\n', at + 1);
  text.replace(at + 1, end - at - 1, key + " = " + value);
}

// The series.csv row nearest to time t, as column name -> value.
std::map<std::string, double> row_at(const fs::path& series, double t) {
  std::ifstream in(series);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream ss(line); std::getline(ss, line, ',');) names.push_back(line);
  std::map<std::string, double> best;
  double best_dt = INFINITY;
  while (std::getline(in, line)) {
    std::map<std::string, double> row;
    std::stringstream ss(line);
    std::string cell;
    for (std::size_t k = 0; k < names.size() && std::getline(ss, cell, ','); ++k)
      row[names[k]] = std::strtod(cell.c_str(), nullptr);
    if (std::abs(row["time_s"] - t) < best_dt) best_dt = std::abs(row["time_s"] - t), best = row;
  }
  return best;
}

struct Window {
  double density, pressure, temperature;
};

Window run_porous(double cell, const fs::path& dir) {
  std::ifstream example(fs::path(SHOCKFIELD_SOURCE_DIR) / "examples/mpm_porous_al/case.toml");
  std::string text{std::istreambuf_iterator<char>(example), {}};
  replace_line(text, "cell_size", std::to_string(cell));
  replace_line(text, "spacing", std::to_string(cell / 2));
  replace_line(text, "end_time", "250e-9");
  replace_line(text, "field_interval", "250e-9");
  replace_line(text, "histogram_times", "[250e-9]");
  const fs::path case_file = dir / "case.toml", out = dir / "run";
  std::ofstream(case_file) << text;
  RunOptions o;
  o.case_file = case_file;
  o.output = out;
  o.quiet = true;
  o.overwrite = true;
  const Config root = Config::load(case_file);
  root.get_string("method");
  mpm::run_case(root, o);
  auto r = row_at(out / "series.csv", 250e-9);
  EXPECT_NEAR(r["time_s"], 250e-9, 3e-9);
  return {r["bottom_h800um_density_mean_kg_m3"], r["bottom_h800um_pressure_mean_Pa"],
          r["bottom_h800um_temperature_mean_K"]};
}

}  // namespace

TEST(MpmSlow, PorousResolution) {
  const fs::path base =
      shockfield::testing::scratch_path("shockfield_mpm_porous");
  for (double cell : {20e-6, 10e-6}) {
    const fs::path dir = base / std::to_string(static_cast<int>(std::lround(cell * 1e6)));
    fs::create_directories(dir);
    const Window w = run_porous(cell, dir);
    EXPECT_NEAR(w.density, 3140.0, 0.02 * 3140.0) << cell;
    EXPECT_NEAR(w.pressure, 16.7e9, 0.05 * 16.7e9) << cell;
    EXPECT_GT(w.temperature, 488.0) << cell;
    const std::string tag = std::to_string(static_cast<int>(std::lround(cell * 1e6))) + "um";
    RecordProperty("density_" + tag, std::to_string(w.density));
    RecordProperty("pressure_" + tag, std::to_string(w.pressure));
    RecordProperty("temperature_" + tag, std::to_string(w.temperature));
    std::printf("cell %s: rho %.1f kg/m^3  P %.3f GPa  T %.1f K\n", tag.c_str(), w.density,
                w.pressure / 1e9, w.temperature);
  }
  fs::remove_all(base);
}
