// Per-atom equality with LAMMPS (Debian lammps 20220106) on the fixtures of
// tests/fixtures/lammps_structure (regenerate.sh): `cna/atom` codes and `coord/atom` counts
// identical, `centro/atom` to 1e-10 relative. Positions are read at full precision, so both
// codes see the same atoms; what remains is round-off in the order of sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::analysis::atoms {
namespace {

struct PeerCase {
  std::string name;
  double cutoff;  // the cna/atom and coord/atom cutoff of regenerate.sh, Å
  int csp_neighbors;
};

void PrintTo(const PeerCase& c, std::ostream* os) { *os << c.name; }

class LammpsPeer : public ::testing::TestWithParam<PeerCase> {};

TEST_P(LammpsPeer, CnaCentroCoordPerAtom) {
  const PeerCase& c = GetParam();
  const std::string file = "fixtures/lammps_structure/" + c.name + ".dump";
  const auto dumps = io::read_dump(file);
  ASSERT_EQ(dumps.size(), 1u);
  const io::DumpFrame& dump = dumps.front();
  const AtomFrame frame = frame_from_dump(dump, file);
  StructureAnalyses a;
  a.coordination = Coordination{c.cutoff};
  a.cna = ConventionalCna{c.cutoff};
  a.centro_symmetry = CentroSymmetry{c.csp_neighbors};
  const auto r = analyze_structure(frame, a);
  const auto& cna = dump.column("c_cna");
  const auto& csp = dump.column("c_csp");
  const auto& coord = dump.column("c_coord");
  std::size_t cna_diff = 0, coord_diff = 0, csp_diff = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    cna_diff += structure_code(r.cna->structure[i]) != static_cast<int>(cna[i]);
    coord_diff += r.coordination[i] != static_cast<int>(coord[i]);
    // 1e-10 relative; perfect-lattice values are round-off (~1e-28 Å²), so differences below
    // 1e-10 Å² (a millionth of the smallest thermal CSP here) count as equal too.
    const double tol = 1e-10 * std::max(std::abs(csp[i]), 1.0);
    if (std::abs(r.centro_symmetry[i] - csp[i]) > tol) {
      if (csp_diff < 5) ADD_FAILURE() << "atom id " << frame.ids[i] << " csp " << r.centro_symmetry[i] << " LAMMPS " << csp[i];
      ++csp_diff;
    }
  }
  EXPECT_EQ(cna_diff, 0u) << c.name;
  EXPECT_EQ(coord_diff, 0u) << c.name;
  EXPECT_EQ(csp_diff, 0u) << c.name;
}

// CNA cutoffs: 0.8536 a for fcc Cu (a = 3.615) and hcp of the same nearest-neighbour distance,
// 1.2071 a for bcc Fe (a = 2.8553).
INSTANTIATE_TEST_SUITE_P(Fixtures, LammpsPeer,
                         ::testing::Values(PeerCase{"cu_fcc_perfect", 3.0858, 12}, PeerCase{"hcp_perfect", 3.0858, 12},
                                           PeerCase{"fe_bcc_perfect", 3.4466, 8},
                                           PeerCase{"cu_stacking_fault", 3.0858, 12},
                                           PeerCase{"cu_thermal_600K", 3.0858, 12},
                                           PeerCase{"fe_thermal_500K", 3.4466, 8},
                                           PeerCase{"cu_void_300K", 3.0858, 12}, PeerCase{"cu_shocked", 3.0858, 12},
                                           // triclinic cells: sheared thermal fcc, tilted bcc
                                           PeerCase{"cu_fcc_tilted", 3.0858, 12}, PeerCase{"fe_bcc_tilted", 3.4466, 8}),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace shockfield::analysis::atoms
