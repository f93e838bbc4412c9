// Thread-count independence: the same evaluation on 1 and 2 OpenMP threads agrees to round-off
// (the private per-thread buffers are summed in a different grouping, nothing else changes).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

Evaluation evaluate_on(int threads, const System& system, Potential& potential) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Evaluation e = evaluate(system, potential, true);
  omp_set_num_threads(saved);
  return e;
}

// `fixture`: a dump under fixtures/, without ".dump".
void expect_same(const std::string& fixture, const std::string& toml) {
  const System system = load_dump_system("fixtures/" + fixture + ".dump");
  auto potential = potential_from_toml(toml, system.atoms.ntypes());
  const Evaluation one = evaluate_on(1, system, *potential);
  const Evaluation two = evaluate_on(2, system, *potential);
  EXPECT_NEAR(one.result.energy, two.result.energy, 1e-12 * std::abs(one.result.energy));
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(one.result.virial[k], two.result.virial[k], 1e-12 * one.result.virial.norm());
  for (std::size_t i = 0; i < system.atoms.nlocal; ++i) {
    EXPECT_LT((one.force[i] - two.force[i]).norm(), 1e-12) << fixture << " atom " << i;
    EXPECT_NEAR(one.result.energy_atom[i], two.result.energy_atom[i], 1e-12);
    EXPECT_LT((one.result.virial_atom[i] - two.result.virial_atom[i]).norm(), 1e-12);
  }
}

TEST(Threads, EamResultsDoNotDependOnTheThreadCount) {
  expect_same("lammps/cuni_void", "[potential]\nstyle = \"eam/alloy\"\nfile = \"CuNi.eam.alloy\"\n"
                           "elements = [\"Cu\", \"Ni\"]\n");
}

TEST(Threads, AdpResultsDoNotDependOnTheThreadCount) {
  expect_same("lammps_adp/alcu_sheared_void", "[potential]\nstyle = \"adp\"\nfile = \"AlCu.adp\"\n"
                                             "elements = [\"Al\", \"Cu\"]\n");
}

TEST(Threads, LjResultsDoNotDependOnTheThreadCount) {
  expect_same("lammps/lj_void", "[potential]\nstyle = \"lj/cut\"\ncutoff = 8.5\nepsilon = 0.0104\n"
                         "sigma = 3.4\n");
}

TEST(Threads, TableResultsDoNotDependOnTheThreadCount) {
  expect_same("lammps_table/spline_300_cut",
              "[potential]\nstyle = \"table\"\ninterpolation = \"spline\"\npoints = 300\n"
              "file = \"fixtures/lammps_table/pair.table\"\nkeyword = \"M12\"\n");
}

}  // namespace
}  // namespace shockfield::md::potentials::testing
