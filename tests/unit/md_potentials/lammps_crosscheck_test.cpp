// Cross-check against LAMMPS 29 Sep 2021 on the same atoms (fixtures/lammps, regenerate.sh):
// total energy, per-atom energy, per-atom force, per-atom virial and the total virial.
// Criterion: the ∞-norm-relative deviation max_k |ours_k - lammps_k| / max_k |lammps_k| over all
// atoms and components must be below 1e-9 (LAMMPS prints 12 significant digits, so the floor
// is about 5e-13; the sums differ from LAMMPS's only in order).
// Triclinic cells (fixtures/lammps_triclinic, regenerate.sh there): lattices in prisms with one,
// two or three tilt factors, affinely sheared further, one with a void and one thinner than the
// cutoff along z (several ghost layers across tilted faces). Criterion 1e-12: those fixtures are
// written in %.17g, so the floor is the round-off of the sums (~1e-15 relative to the largest
// term) plus the box edges rebuilt from the dump's bounding box (1 ulp).
// ADP (fixtures/lammps_adp, regenerate.sh there): Ni.adp with a vacancy and compressed beyond its
// density table, AlCu.adp as a random alloy, compressed, and sheared in a tilted cell with a void;
// written in %.17g, criterion 1e-12 for the same reason. One deliberate difference: beyond the
// F(rho) table (rho > rhomax, only the Ni cell compressed to V/V0 = 0.22) LAMMPS 29 Sep 2021's
// adp holds F at F(rhomax) while its force uses F'(rhomax), so its energy is not the integral of
// its forces; shockfield extends F linearly as LAMMPS's eam styles do (docs/md.md, ADP). That
// case compares with LAMMPS's per-atom energy plus exactly F'(rho_i)(rho_i - rhomax).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "shockfield/md/potentials/adp.hpp"
#include "shockfield/md/potentials/eam.hpp"
#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

constexpr double kTolerance = 1e-9;
constexpr double kTriclinicTolerance = 1e-12;

struct Case {
  std::string name;     // fixture base name
  std::string toml;     // the [potential] table
  std::string folder = "lammps";
  double tolerance = kTolerance;
  EnergyCorrection correction = {};
};

// ADP beyond the density table: our energy minus LAMMPS 2021's, F'(rho_i)(rho_i - rhomax).
double adp_linear_extension(const Potential& potential, const Atoms& atoms, std::size_t i) {
  const auto& adp = dynamic_cast<const AdpPotential&>(potential);
  const double rho = adp.density()[i], rhomax = adp.tables().rhomax;
  return rho > rhomax ? embedding(adp.tables(), atoms.type[i], rho).slope * (rho - rhomax) : 0.0;
}

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

const std::string kNiAdp = "[potential]\nstyle = \"adp\"\nfile = \"Ni.adp\"\nelements = [\"Ni\"]\n";
const std::string kAlCuAdp =
    "[potential]\nstyle = \"adp\"\nfile = \"AlCu.adp\"\nelements = [\"Al\", \"Cu\"]\n";

class LammpsCrossCheck : public ::testing::TestWithParam<Case> {};

TEST_P(LammpsCrossCheck, EnergyForcesAndVirialMatchLammps) {
  const Case& c = GetParam();
  const LammpsDeviation d = compare_with_lammps("fixtures/" + c.folder + "/" + c.name, c.toml, c.correction);
  EXPECT_EQ(load_dump_system("fixtures/" + c.folder + "/" + c.name + ".dump").box.triclinic(),
            c.folder == "lammps_triclinic" || c.name == "alcu_sheared_void");
  d.print(c.name);
  d.expect_below(c.tolerance);
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

// Likewise for ADP: the compressed nickel reaches beyond Ni.adp's F(rho) table (so the correction
// above is exercised).
TEST(LammpsCrossCheckCoverage, CompressedNickelExceedsTheAdpDensityTable) {
  const System system = load_dump_system("fixtures/lammps_adp/ni_compressed.dump");
  auto potential = potential_from_toml(kNiAdp, 1);
  evaluate(system, *potential);
  const auto& adp = dynamic_cast<const AdpPotential&>(*potential);
  const auto rho = adp.density();
  EXPECT_GT(*std::max_element(rho.begin(), rho.end()), adp.tables().rhomax);
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

INSTANTIATE_TEST_SUITE_P(
    Triclinic, LammpsCrossCheck,
    ::testing::Values(Case{"cu_u3_tilt_xy", kCuU3, "lammps_triclinic", kTriclinicTolerance},
                      Case{"cu_u3_sheared_void", kCuU3, "lammps_triclinic", kTriclinicTolerance},
                      Case{"fe_mm_tilt_xz_yz", kFeMm, "lammps_triclinic", kTriclinicTolerance},
                      Case{"lj_thin_tilted", kLj, "lammps_triclinic", kTriclinicTolerance}),
    [](const auto& info) { return info.param.name; });

INSTANTIATE_TEST_SUITE_P(
    Adp, LammpsCrossCheck,
    ::testing::Values(Case{"ni_vacancy", kNiAdp, "lammps_adp", kTriclinicTolerance},
                      Case{"ni_compressed", kNiAdp, "lammps_adp", kTriclinicTolerance, adp_linear_extension},
                      Case{"alcu_random", kAlCuAdp, "lammps_adp", kTriclinicTolerance},
                      Case{"alcu_compressed", kAlCuAdp, "lammps_adp", kTriclinicTolerance},
                      Case{"alcu_sheared_void", kAlCuAdp, "lammps_adp", kTriclinicTolerance}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace shockfield::md::potentials::testing
