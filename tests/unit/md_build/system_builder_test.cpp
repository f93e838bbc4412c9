// The [system] table: crystals and data files, deleted regions, groups, the overlap check, and
// errors that name the file, key and line.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>

#include "shockfield/core/error.hpp"
#include "shockfield/md/system_builder.hpp"

namespace shockfield::md {
namespace {

// Parses `toml` as if it were fixtures/io/case.toml (data files are found next to it) and builds
// its [system] table.
BuiltSystem build(const std::string& toml, const Config** keep = nullptr) {
  static std::optional<Config> root;
  root = Config::parse(toml, "fixtures/io/case.toml");
  if (keep) *keep = &*root;
  return build_system(root->table("system"));
}

void expect_build_error(const std::string& toml, const std::string& fragment) {
  try {
    build(toml);
    FAIL() << "no error for:\n" << toml;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

const std::string fcc = R"(
[system.lattice]
style = "fcc"
a0 = 3.615
orient_x = [1, -1, 0]
orient_y = [1, 1, -2]
orient_z = [1, 1, 1]
repeat = [6, 4, 3]
boundary = "ppf"
masses = [63.546]
elements = ["Cu"]
)";

// `run --check` counts a crystal larger than a few cells without building it; the count must be
// the built crystal's for every boundary, the hi faces of shrink-wrapped axes included.
TEST(SystemBuilder, CheckCountsTheAtomsTheRunCreates) {
  for (const std::string boundary : {"ppp", "ppf", "pps", "sfs", "sss"}) {
    SCOPED_TRACE(boundary);
    std::string toml = fcc;
    toml.replace(toml.find("\"ppf\""), 5, "\"" + boundary + "\"");
    const Config root = Config::parse(toml, "fixtures/io/case.toml");
    const BuiltSystem counted = build_system(root.table("system"), true);
    const BuiltSystem built = build_system(root.table("system"));
    ASSERT_FALSE(counted.counted_types.empty());  // 6 cells along x: counted, not built
    EXPECT_EQ(counted.atom_count(), built.atoms.nlocal);
  }
}

TEST(SystemBuilder, CrystalWithVoidAndGroups) {
  const Config* root = nullptr;
  const BuiltSystem s = build(R"(
[system]
min_distance = 2.0
[[system.delete]]
shape = "sphere"
center = [7.9, 8.3, 9.1]
radius = 5.0
[[system.group]]
name = "bottom"
shape = "block"
zhi = 3.0
[[system.group]]
name = "copper"
types = [1]
)" + fcc, &root);
  EXPECT_EQ(s.atoms.nlocal, 389u);  // 432 sites, 43 in the void (LAMMPS: fixtures/io/lattice_fcc111)
  EXPECT_EQ(s.box.boundary[2], geometry::Boundary::fixed);
  EXPECT_EQ(s.atoms.type_names[0], "Cu");
  EXPECT_EQ(s.atoms.mass[0], 63.546);
  const std::uint32_t bottom = s.groups.find("bottom"), copper = s.groups.find("copper");
  std::size_t in_bottom = 0;
  for (std::size_t i = 0; i < s.atoms.nlocal; ++i) {
    in_bottom += (s.atoms.mask[i] & bottom) != 0;
    EXPECT_EQ((s.atoms.mask[i] & bottom) != 0, s.atoms.x[i].z() <= 3.0);
    EXPECT_TRUE(s.atoms.mask[i] & copper);
    EXPECT_TRUE(s.atoms.mask[i] & 1u);
  }
  EXPECT_GT(in_bottom, 0u);
  root->check_unknown_keys();
  const std::string resolved = root->resolved_toml();
  EXPECT_NE(resolved.find("atoms = 389"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("atoms_deleted = 43"), std::string::npos) << resolved;
}

TEST(SystemBuilder, DataFileWithBoundaryMassesAndElements) {
  const BuiltSystem s = build(R"(
[system]
data_file = "data_fcc.data"
boundary = "ppf"
masses = [1.0, 2.0]
elements = ["Cu", "Ni"]
)");
  EXPECT_EQ(s.atoms.nlocal, 32u);
  EXPECT_EQ(s.atoms.mass, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(s.atoms.type_names[1], "Ni");
  EXPECT_EQ(s.atoms.v[0].x(), -0.5647194065870035);
  const BuiltSystem from_file = build("[system]\ndata_file = \"data_fcc.data\"\n");
  // The Masses section is the fallback after the potential file's masses (LAMMPS: pair_coeff
  // sets them after read_data), so it is kept aside and the types start without a mass.
  EXPECT_EQ(from_file.file_masses, (std::vector<double>{63.546, 58.6934}));
  EXPECT_EQ(from_file.atoms.mass, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(s.file_masses, from_file.file_masses);
}

TEST(SystemBuilder, TypesWithoutMassKeepZero) {
  const BuiltSystem s = build("[system.lattice]\nstyle = \"bcc\"\na0 = 2.86\nrepeat = [2, 2, 2]\nbasis_types = [1, 2]\n");
  EXPECT_EQ(s.atoms.mass, (std::vector<double>{0.0, 0.0}));  // taken from the potential later
  EXPECT_EQ(s.atoms.nlocal, 16u);
}

TEST(SystemBuilder, Overlap) {
  const std::string path = shockfield::testing::scratch_path("overlap.data").string();
  std::ofstream(path) << "t\n2 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n"
                         "Atoms\n\n1 1 0.01 5 5\n2 1 9.96 5 5\n";
  // The two atoms are 0.05 Å apart across the periodic x face.
  expect_build_error("[system]\ndata_file = \"" + path + "\"\n",
                     "fixtures/io/case.toml: key 'system.min_distance': atoms 1 and 2 are 0.05 Å apart, closer than 0.1 Å");
  EXPECT_NO_THROW(build("[system]\ndata_file = \"" + path + "\"\nmin_distance = 0.01\n"));
  EXPECT_NO_THROW(build("[system]\ndata_file = \"" + path + "\"\nboundary = \"fpp\"\n"));  // x not periodic: far apart
}

TEST(SystemBuilder, Errors) {
  expect_build_error("[system]\nmin_distance = 1.0\n", "expected exactly one of [system.lattice]");
  expect_build_error("[system]\ndata_file = \"data_fcc.data\"\n" + fcc, "expected exactly one of");
  expect_build_error("[system]\ndata_file = \"missing.data\"\n", "fixtures/io/missing.data: cannot open");
  expect_build_error("[system]\ndata_file = \"data_fcc.data\"\nboundary = \"pp\"\n", "key 'system.boundary': expected three letters");
  expect_build_error("[system]\ndata_file = \"data_fcc.data\"\nboundary = \"ppx\"\n", "key 'system.boundary'");
  const std::string outside = shockfield::testing::scratch_path("outside.data").string();
  std::ofstream(outside) << "t\n1 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\nAtoms\n\n1 1 5 5 10.5\n";
  expect_build_error("[system]\ndata_file = \"" + outside + "\"\nmasses = [1.0]\nboundary = \"ppf\"\n",
                     "outside.data:9: atom 1 at z = 10.5 is outside the non-periodic box");
  expect_build_error("[system]\ndata_file = \"data_fcc.data\"\nelements = [\"Cu\"]\n", "key 'system.elements': expected 2 element names");
  const std::string lat = "[system.lattice]\nstyle = \"fcc\"\na0 = 3.6\nrepeat = [2, 2, 2]\n";
  expect_build_error(lat + "orient_x = [1, 1, 0]\n", "case.toml:5: key 'system.lattice.orient_x': lattice orient x=[1,1,0] y=[0,1,0] z=[0,0,1]: the vectors are not orthogonal");
  expect_build_error(lat + "orient_x = [1.5, 0, 0]\n", "key 'system.lattice.orient_x': expected three integers");
  expect_build_error(lat + "c_over_a = 1.6\n", "key 'system.lattice.c_over_a'");
  expect_build_error(lat + "basis_types = [1, 2]\n", "key 'system.lattice.basis_types'");
  expect_build_error(lat + "masses = [1.0]\nbasis_types = [1, 2, 1, 1]\n", "key 'system.lattice.basis_types'");
  expect_build_error("[system.lattice]\nstyle = \"bct\"\na0 = 3.6\nrepeat = [2, 2, 2]\n", "key 'system.lattice.style'");
  expect_build_error("[system.lattice]\nstyle = \"fcc\"\na0 = 3.6\nrepeat = [0, 2, 2]\n", "key 'system.lattice.repeat'");
  expect_build_error("[system.lattice]\nstyle = \"fcc\"\nrepeat = [1, 2, 2]\n", "key 'system.lattice.a0'");
  expect_build_error("[system]\n[[system.group]]\nname = \"all\"\ntypes = [1]\n" + lat, "'all' is predefined");
  expect_build_error("[system]\n[[system.group]]\nname = \"g\"\n" + lat, "expected exactly one of shape");
  expect_build_error("[system]\n[[system.group]]\nname = \"g\"\ntypes = [2]\n" + lat, "key 'system.group[0].types'");
  expect_build_error("[system]\n[[system.delete]]\nshape = \"block\"\n" + lat, "the system has no atoms");
}

}  // namespace
}  // namespace shockfield::md
