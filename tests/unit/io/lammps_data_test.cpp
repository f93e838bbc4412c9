// LAMMPS data files: a file written by LAMMPS write_data (fixtures/io/data_fcc.in) is read and
// written back byte for byte; round trips; comments; every kind of malformed input.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/io/lammps_data.hpp"

namespace shockfield::io {
namespace {

using geometry::Boundary;
constexpr std::array<Boundary, 3> ppf{Boundary::periodic, Boundary::periodic, Boundary::fixed};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = shockfield::testing::scratch_path(name).string();
  std::ofstream(path) << text;
  return path;
}

void expect_data_error(const std::string& text, const std::string& fragment,
                       const std::array<Boundary, 3>& boundary = ppf) {
  const std::string path = temp_file("bad.data", text);
  try {
    read_data(path, boundary);
    FAIL() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.data"), std::string::npos) << e.what();
  }
}

TEST(LammpsData, ReadsLammpsWriteData) {
  const DataFile d = read_data("fixtures/io/data_fcc.data", ppf);
  EXPECT_EQ(d.atoms.nlocal, 32u);
  EXPECT_EQ(d.atoms.ntypes(), 2);
  EXPECT_EQ(d.atoms.mass, (std::vector<double>{63.546, 58.6934}));
  EXPECT_TRUE(d.has_velocities);
  EXPECT_DOUBLE_EQ(d.box.hi.z(), 7.23);
  EXPECT_EQ(d.box.boundary[2], Boundary::fixed);
  EXPECT_EQ(d.atoms.id[0], 1);
  EXPECT_DOUBLE_EQ(d.atoms.x[0].x(), 6.73);
  EXPECT_EQ(d.atoms.image[0], (std::array<int, 3>{1, 0, 0}));
  EXPECT_EQ(d.atoms.type[1], 1);
  EXPECT_DOUBLE_EQ(d.atoms.v[0].x(), -0.5647194065870035);
}

TEST(LammpsData, WritesTheSameTextAsLammps) {
  const std::string path = "fixtures/io/data_fcc.data";
  const DataFile d = read_data(path, ppf);
  const std::string out = shockfield::testing::scratch_path("rewritten.data").string();
  write_data(out, d.box, d.atoms, {.title = d.title});
  EXPECT_EQ(slurp(out), slurp(path));
}

TEST(LammpsData, TriclinicWrittenByLammpsReadsAndWritesBack) {
  const std::string path = "fixtures/io/data_triclinic.data";
  const DataFile d = read_data(path);
  EXPECT_EQ(d.box.tilt, Vec3(3.615, -3.615, 1.8075));
  EXPECT_EQ(d.atoms.image[0], (std::array<int, 3>{1, -1, 1}));
  for (std::size_t i = 0; i < d.atoms.nlocal; ++i) EXPECT_TRUE(d.box.contains(d.atoms.x[i])) << i;
  const std::string out = shockfield::testing::scratch_path("rewritten_triclinic.data").string();
  write_data(out, d.box, d.atoms, {.title = d.title});
  EXPECT_EQ(slurp(out), slurp(path));
}

TEST(LammpsData, AtomsOutsideATiltedCellAreWrappedByItsEdges) {
  // x = lo - b/2 lies outside across the b face: wrapped by +b, image -1 along y
  const std::string text = "t\n2 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n4 0 0 xy xz yz\n\nMasses\n\n1 1\n\nAtoms\n\n1 1 -1 -5 5\n2 1 1 1 1\n";
  const std::string path = shockfield::testing::scratch_path("tilted.data").string();
  std::ofstream(path) << text;
  const DataFile d = read_data(path);
  EXPECT_EQ(d.atoms.image[0], (std::array<int, 3>{0, -1, 0}));
  EXPECT_LT((d.atoms.x[0] - Vec3(3, 5, 5)).norm(), 1e-14);
}

TEST(LammpsData, RoundTripIsExact) {
  md::Atoms atoms;
  atoms.mass = {26.9815385, 1.0 / 3.0};
  atoms.type_names = {"Al", ""};
  atoms.add(Vec3(0.1, 1.0 / 7.0, 2.0 / 3.0), 0, 5, Vec3(1e-17, -2.5, 1.0 / 3.0));
  atoms.add(Vec3(9.999999999999998, 0, 5), 1, 2);
  atoms.image[1] = {-3, 0, 7};
  geometry::Box box;
  box.lo = Vec3(0, -1.0 / 9.0, 0);
  box.hi = Vec3(10, 10, 10);
  const std::string path = shockfield::testing::scratch_path("roundtrip.data").string();
  write_data(path, box, atoms);
  const DataFile d = read_data(path);
  EXPECT_EQ(d.box.lo, box.lo);
  EXPECT_EQ(d.atoms.x, atoms.x);
  EXPECT_EQ(d.atoms.v, atoms.v);
  EXPECT_EQ(d.atoms.id, atoms.id);
  EXPECT_EQ(d.atoms.type, atoms.type);
  EXPECT_EQ(d.atoms.image, atoms.image);
  EXPECT_EQ(d.atoms.mass, atoms.mass);
  EXPECT_EQ(d.atoms.type_names, atoms.type_names);
}

const std::string head = "title\n2 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n";

TEST(LammpsData, CommentsBlankLinesSkippedSectionsAndWrapping) {
  const std::string text =
      "# title line\n\n  2 atoms   # two of them\n1 atom types\n0 bonds\n\n"
      "0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\n# a comment line\n"
      "Pair Coeffs # lj/cut\n\n1 0.4 2.3\n\nMasses\n\n1 1.008 # H\n\n"
      "Atoms # atomic\n\n7 1 -1 2 3\n\n3 1 10 2 10 0 0 0 # on the faces\n";
  const DataFile d = read_data(temp_file("ok.data", text), ppf);
  EXPECT_EQ(d.atoms.type_names[0], "H");
  EXPECT_FALSE(d.has_velocities);
  EXPECT_EQ(d.atoms.x[0], Vec3(9, 2, 3));  // remapped into the periodic box, as read_data does
  EXPECT_EQ(d.atoms.image[0], (std::array<int, 3>{-1, 0, 0}));
  EXPECT_EQ(d.atoms.x[1], Vec3(0, 2, 10));  // x wraps at the periodic hi face; z = zhi is inside
}

// LAMMPS write_data semantics: the positions wrapped into the periodic box and the shrink-wrapped
// dimension reset to the atoms (padded by the margin) before writing, so that LAMMPS read_data and
// read_data() assign every atom. Before, the box was written as given: an atom that had moved
// past a shrink-wrapped face since the last neighbour rebuild made the file unreadable.
TEST(LammpsData, WriteResetsAShrinkWrappedBoxToTheAtoms) {
  md::Atoms atoms;
  atoms.mass = {63.546};
  atoms.add(Vec3(10.5, 2, -0.5), 0, 1);  // past the periodic x face and the stale z face
  atoms.add(Vec3(3, 4, 12.25), 0, 2);    // past the stale z hi face
  geometry::Box box;
  box.hi = Vec3(10, 10, 10);
  box.boundary = {Boundary::periodic, Boundary::periodic, Boundary::shrink};
  const md::Atoms before = atoms;
  const std::string path = shockfield::testing::scratch_path("shrink.data").string();
  write_data(path, box, atoms, {.shrink_margin = Vec3(0, 0, 0.25)});
  EXPECT_EQ(atoms.x, before.x);  // the caller's atoms and box are not changed
  EXPECT_EQ(box.hi.z(), 10.0);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));  // written through a temporary + rename
  const DataFile d = read_data(path, box.boundary);
  ASSERT_EQ(d.atoms.nlocal, 2u);
  EXPECT_EQ(d.box.lo.z(), -0.75);
  EXPECT_EQ(d.box.hi.z(), 12.5);
  EXPECT_EQ(d.box.hi.x(), 10.0);
  EXPECT_EQ(d.atoms.x[0], Vec3(0.5, 2, -0.5));
  EXPECT_EQ(d.atoms.image[0], (std::array<int, 3>{1, 0, 0}));
  // The default margin: 1e-4 × the length of the box given (LAMMPS Domain::small).
  write_data(path, box, atoms);
  EXPECT_DOUBLE_EQ(read_data(path, box.boundary).box.lo.z(), -0.5 - 1e-3);
}

// LAMMPS read_data grows a shrink-wrapped dimension by 1e-4 × its length on each side before it
// assigns the atoms (Domain::set_initial_box); an atom inside that margin is read, one beyond it
// is refused, and a fixed dimension has no margin.
TEST(LammpsData, ReadAcceptsAtomsWithinTheShrinkWrapMargin) {
  const std::string text = head + "\nAtoms\n\n1 1 0 0 0\n2 1 1 1 10.0009\n";  // margin 1e-3
  const std::array<Boundary, 3> pps{Boundary::periodic, Boundary::periodic, Boundary::shrink};
  EXPECT_EQ(read_data(temp_file("margin.data", text), pps).atoms.nlocal, 2u);
  expect_data_error(text, "outside the non-periodic box", ppf);
  expect_data_error(head + "\nAtoms\n\n1 1 0 0 0\n2 1 1 1 10.0011\n", "shrink-wrapped: 0.001", pps);
}

TEST(LammpsData, MalformedInput) {
  const std::string masses = "\nMasses\n\n1 1.0\n";
  expect_data_error("", "unexpected end of file, expected the title line");
  expect_data_error(head + masses + "\nAtoms # atomic\n\n1 1 0 0 0\n", "bad.data:15: unexpected end of file, expected line 2 of 2 in the Atoms section");
  expect_data_error(head + "\nAtoms\n\n1 1 0 0\n", "bad.data:10: expected 5 values");
  expect_data_error(head + "\nAtoms\n\n1 1 0 0 0 0 0\n", "got 7");
  expect_data_error(head + "\nAtoms\n\n1 1 0 0 0\n1 1 1 1 1\n", "bad.data:11: duplicate atom id 1");
  expect_data_error(head + "\nAtoms\n\n1 2 0 0 0\n", "bad.data:10: atom type 2 out of range 1..1");
  expect_data_error(head + "\nAtoms\n\n1 1 0 0 0\n2 1 1 1 10.5\n", "bad.data:11: atom 2 at z = 10.5 is outside the non-periodic box");
  expect_data_error(head + "\nAtoms\n\n1 1 0 -1 0\n2 1 0 0 0\n", "outside the non-periodic box",
                    {Boundary::periodic, Boundary::shrink, Boundary::periodic});
  expect_data_error(head + "\nAtoms\n\n0 1 0 0 0\n", "atom id >= 1");
  expect_data_error(head + "\nAtoms\n\n1 1 0 a 0\n", "bad.data:10: expected y");
  expect_data_error(head + "\nAtoms # full\n\n", "atom style 'full' is not supported");
  expect_data_error(head + masses + "\nAtoms\n\n1 1 0 0 0\n2 1 1 1 1\n\nVelocities\n\n1 0 0 0\n9 0 0 0\n",
                    "bad.data:20: velocity for atom id 9");
  expect_data_error(head + "\nVelocities\n\n", "must come after the Atoms section");
  expect_data_error(head + "\nMasses\n\n1 -1\n", "expected a mass > 0");
  expect_data_error(head + "\nMasses\n\n1 1 1\n", "expected 'type mass'");
  expect_data_error(head + "\nBonds\n\n", "unsupported section 'Bonds'");
  expect_data_error(head, "declares 2 atoms but there is no Atoms section");
  expect_data_error("t\n2 atoms\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\nAtoms\n", "no 'N atom types' line");
  expect_data_error("t\n2 atoms\n1 atom types\n0 10 xlo xhi\n0 10 zlo zhi\nAtoms\n", "no 'ylo yhi' line");
  expect_data_error("t\n2 atoms\n1 atom types\n5 1 xlo xhi\n", "bad.data:4: expected xlo < xhi");
  expect_data_error(head + "6 0 0 xy xz yz\n", "bad.data: the 'xy xz yz' header line: tilt xy = 6 is beyond LAMMPS's limit");
  expect_data_error(head + "0 0 6 xy xz yz\n", "tilt yz = 6", {Boundary::periodic, Boundary::periodic, Boundary::periodic});
  expect_data_error(head + "0 nan 0 xy xz yz\n", "bad.data:7: expected xz (a finite number)");
  expect_data_error(head + "0 1 0 xy xz yz\n", "needs a periodic z boundary", ppf);
  expect_data_error("t\n2 atoms\n3 bonds\n", "only atom style atomic");
  expect_data_error("t\n2 atoms\n3 things\n", "bad.data:3: unknown header line '3 things'");
  EXPECT_THROW(read_data("fixtures/io/no_such.data"), InputError);
}

}  // namespace
}  // namespace shockfield::io
