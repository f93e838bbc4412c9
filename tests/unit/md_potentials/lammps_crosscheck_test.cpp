// Cross-check against LAMMPS 29 Sep 2021 on the same atoms (fixtures/lammps, regenerate.sh):
// total energy, per-atom energy, per-atom force, per-atom virial and the total virial.
// Criterion: the ∞-norm-relative deviation max_k |ours_k - lammps_k| / max_k |lammps_k| over all
// atoms and components must be below 1e-9 (LAMMPS prints 12 significant digits, so the floor
// is about 5e-13; the sums differ from LAMMPS's only in order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "shockfield/core/units.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/potentials/eam.hpp"
#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

constexpr double kTolerance = 1e-9;

struct Case {
  std::string name;     // fixture base name
  std::string toml;     // the [potential] table
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.name; }

const std::string kCuU3 = "[potential]\nstyle = \"eam\"\nfile = \"Cu_u3.eam\"\n";
const std::string kAlZhou =
    "[potential]\nstyle = \"eam/alloy\"\nfile = \"Al_zhou.eam.alloy\"\nelements = [\"Al\"]\n";
const std::string kFeMm =
    "[potential]\nstyle = \"eam/fs\"\nfile = \"Fe_mm.eam.fs\"\nelements = [\"Fe\"]\n";
const std::string kCuNi =
    "[potential]\nstyle = \"eam/alloy\"\nfile = \"CuNi.eam.alloy\"\nelements = [\"Cu\", \"Ni\"]\n";
const std::string kAlFe =
    "[potential]\nstyle = \"eam/fs\"\nfile = \"AlFe_mm.eam.fs\"\nelements = [\"Fe\", \"Al\"]\n";
const std::string kLj =
    "[potential]\nstyle = \"lj/cut\"\ncutoff = 8.5\nshift = true\n"
    "[[potential.pair]]\ntypes = [1, 1]\nepsilon = 0.0104\nsigma = 3.40\n"
    "[[potential.pair]]\ntypes = [2, 2]\nepsilon = 0.0080\nsigma = 3.00\ncutoff = 7.0\n";

struct Totals {
  double energy = 0, volume = 0;
  Voigt6 pressure_virial = Voigt6::Zero();
};

Totals read_totals(const std::string& file) {
  std::ifstream in(file);
  Totals t;
  std::string key;
  in >> key >> t.energy >> key >> t.volume >> key;
  for (int k = 0; k < 6; ++k) in >> t.pressure_virial[k];
  EXPECT_TRUE(in.good()) << file;
  return t;
}

class LammpsCrossCheck : public ::testing::TestWithParam<Case> {};

TEST_P(LammpsCrossCheck, EnergyForcesAndVirialMatchLammps) {
  const Case& c = GetParam();
  const std::string base = "fixtures/lammps/" + c.name;
  const System system = load_dump_system(base + ".dump");
  const auto frame = io::read_dump(base + ".dump").front();
  const Totals totals = read_totals(base + ".totals");
  auto potential = potential_from_toml(c.toml, system.atoms.ntypes());
  potential->check_types(system.atoms);
  const Evaluation ours = evaluate(system, *potential);

  const std::size_t n = system.atoms.nlocal;
  std::vector<double> f, f_ref, e, e_ref, v, v_ref;
  const char* fcol[3] = {"fx", "fy", "fz"};
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      f.push_back(ours.force[i][d]);
      f_ref.push_back(frame.column(fcol[d])[i]);
    }
    e.push_back(ours.result.energy_atom[i]);
    e_ref.push_back(frame.column("c_pe")[i]);
    for (int k = 0; k < 6; ++k) {
      // compute stress/atom NULL virial = -virial in bar·Å³.
      v.push_back(ours.result.virial_atom[i][k]);
      v_ref.push_back(-frame.column("c_st[" + std::to_string(k + 1) + "]")[i] / units::metal::nktv2p);
    }
  }
  std::vector<double> vt, vt_ref;
  for (int k = 0; k < 6; ++k) {
    vt.push_back(ours.result.virial[k]);
    vt_ref.push_back(totals.pressure_virial[k] * totals.volume / units::metal::nktv2p);
  }
  const double de = std::abs(ours.result.energy - totals.energy) / std::abs(totals.energy);
  const double dea = max_norm_relative(e, e_ref);
  const double df = max_norm_relative(f, f_ref);
  const double dv = max_norm_relative(v, v_ref);
  const double dvt = max_norm_relative(vt, vt_ref);
  std::printf("%-18s atoms %4zu  energy %.1e  energy/atom %.1e  force %.1e  virial/atom %.1e  "
              "virial %.1e\n", c.name.c_str(), n, de, dea, df, dv, dvt);
  EXPECT_LT(de, kTolerance);
  EXPECT_LT(dea, kTolerance);
  EXPECT_LT(df, kTolerance);
  EXPECT_LT(dv, kTolerance);
  EXPECT_LT(dvt, kTolerance);
}

// The compressed fixture must reach beyond the F(rho) table, so that LAMMPS's linear extension
// of the embedding energy (rho > rhomax) is part of the comparison above.
TEST(LammpsCrossCheckCoverage, CompressedCopperExceedsTheDensityTable) {
  const System system = load_dump_system("fixtures/lammps/cu_u3_compressed.dump");
  auto potential = potential_from_toml(kCuU3, 1);
  evaluate(system, *potential);
  const auto& eam = dynamic_cast<const EamPotential&>(*potential);
  const double rho_max = *std::max_element(eam.density().begin(), eam.density().end());
  EXPECT_GT(rho_max, eam.tables().rhomax);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, LammpsCrossCheck,
    ::testing::Values(Case{"cu_u3_thermal", kCuU3}, Case{"cu_u3_void", kCuU3},
                      Case{"cu_u3_compressed", kCuU3},
                      Case{"al_zhou_thermal", kAlZhou}, Case{"al_zhou_void", kAlZhou},
                      Case{"fe_mm_thermal", kFeMm}, Case{"fe_mm_void", kFeMm},
                      Case{"cuni_thermal", kCuNi}, Case{"cuni_void", kCuNi},
                      Case{"alfe_mm_thermal", kAlFe}, Case{"lj_thermal", kLj},
                      Case{"lj_void", kLj}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace shockfield::md::potentials::testing
