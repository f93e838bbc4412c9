// Extended XYZ writer: the comment line OVITO and ASE read, species from element names, vector
// properties grouped. Reader: round trips of the writer, ASE's layout, and bad input refused with
// the file and the line.
#include <gtest/gtest.h>

#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/io/extxyz.hpp"

namespace shockfield::io {
namespace {

TEST(ExtXyz, HeaderAndRows) {
  md::Atoms atoms;
  atoms.mass = {63.546, 58.69};
  atoms.add(Vec3(0.5, 1.25, 2), 0, 1, Vec3(1, 2, 3));
  atoms.add(Vec3(1, 2, 3), 1, 2);
  geometry::Box box;
  box.lo = Vec3(-1, 0, 0);
  box.hi = Vec3(9, 10, 20);
  box.boundary[2] = geometry::Boundary::fixed;
  DumpFrame frame = make_dump_frame(40, box, atoms, {"id", "type", "x", "y", "z", "vx", "vy", "vz"});
  frame.set_column("c_pe", {-3.5, -3.25});
  std::ostringstream out;
  write_extxyz_frame(out, frame, {"Cu", ""});
  EXPECT_EQ(out.str(),
            "2\n"
            "Lattice=\"10 0 0 0 10 0 0 0 20\" Origin=\"-1 0 0\" "
            "Properties=species:S:1:pos:R:3:id:I:1:velo:R:3:c_pe:R:1 pbc=\"T T F\" Timestep=40\n"
            "Cu 0.5 1.25 2 1 1 2 3 -3.5\n"
            "2 1 2 3 2 0 0 0 -3.25\n");
}

TEST(ExtXyz, NeedsPositions) {
  DumpFrame frame;
  frame.set_column("id", {1.0});
  std::ostringstream out;
  EXPECT_THROW(write_extxyz_frame(out, frame, {}), InputError);
}

// What the reader refuses: the message names the stream and the line, and says what was wrong.
void expect_refused(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  try {
    read_extxyz(in, "f.xyz");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

DumpFrame two_type_frame() {
  md::Atoms atoms;
  atoms.mass = {63.546, 58.69};
  atoms.add(Vec3(0.5, 1.25, 2), 0, 7, Vec3(1, 2, 3));
  atoms.add(Vec3(1.0 / 3.0, 2, 3), 1, 2, Vec3(-1, 0.1, 0));
  atoms.add(Vec3(8, 9, 19.5), 0, 3);
  geometry::Box box;
  box.lo = Vec3(-1, 0, 0.5);
  box.hi = Vec3(9, 10, 20);
  box.boundary[2] = geometry::Boundary::shrink;
  DumpFrame frame = make_dump_frame(40, box, atoms, {"id", "type", "x", "y", "z", "vx", "vy", "vz"});
  frame.set_column("c_pe", {-3.5, -3.25, -3.125});
  frame.time = 0.04;
  return frame;
}

TEST(ExtXyzReader, RoundTripOfTheWriterTwoFrames) {
  DumpFrame frame = two_type_frame();
  std::ostringstream out;
  write_extxyz_frame(out, frame, {"Cu", "Ni"}, DumpWriteOptions{true});
  frame.timestep = 50;
  write_extxyz_frame(out, frame, {"Cu", "Ni"}, DumpWriteOptions{true});
  std::istringstream in(out.str());
  std::vector<int> lines;
  const auto frames = read_extxyz(in, "f.xyz", &lines);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(lines, (std::vector<int>{1, 6}));
  const DumpFrame& a = frames[0];
  EXPECT_EQ(a.timestep, 40);
  EXPECT_EQ(frames[1].timestep, 50);
  ASSERT_TRUE(a.time.has_value());
  EXPECT_DOUBLE_EQ(*a.time, 0.04);
  EXPECT_EQ(a.element_names, (std::vector<std::string>{"Cu", "Ni"}));
  EXPECT_EQ(a.types(), (std::vector<int>{1, 2, 1}));
  EXPECT_EQ(a.ids(), (std::vector<std::int64_t>{7, 2, 3}));
  const auto x = a.positions(), x0 = frame.positions();
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(x[i], x0[i]);  // full precision: exact
  EXPECT_EQ(a.column("vx"), frame.column("vx"));
  EXPECT_EQ(a.column("vz"), frame.column("vz"));
  EXPECT_EQ(a.column("c_pe"), frame.column("c_pe"));
  EXPECT_EQ(a.box.lo, frame.box.lo);
  EXPECT_EQ(a.box.hi, frame.box.hi);
  EXPECT_EQ(a.box.boundary[0], geometry::Boundary::periodic);
  EXPECT_EQ(a.box.boundary[2], geometry::Boundary::shrink);
  EXPECT_EQ(a.bounds[2], "ss");
}

// A restricted triclinic cell is written as Lattice="lx 0 0 xy ly 0 xz yz lz" and read back.
TEST(ExtXyzReader, RoundTripOfATriclinicCell) {
  DumpFrame frame = two_type_frame();
  frame.box.boundary[2] = geometry::Boundary::periodic;
  frame.box.tilt = Vec3(2.5, -1.0 / 3.0, 4.0);
  std::ostringstream out;
  write_extxyz_frame(out, frame, {"Cu", "Ni"}, DumpWriteOptions{true});
  EXPECT_NE(out.str().find("Lattice=\"10 0 0 2.5 10 0 -0.3333333333333333 4 19.5\""), std::string::npos) << out.str();
  std::istringstream in(out.str());
  const auto back = read_extxyz(in, "f.xyz");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].box.tilt, frame.box.tilt);
  EXPECT_EQ(back[0].box.lo, frame.box.lo);
  EXPECT_EQ(back[0].box.hi, frame.box.hi);
}

TEST(ExtXyzReader, AseLayoutIdsInFileOrderAndNumericSpecies) {
  // ASE writes no Origin and no id; a logical column and an extra string column (left out).
  const std::string text =
      "3\n"
      "Lattice=\"4.0 0.0 0.0 0.0 5.0 0.0 0.0 0.0 6.0\" Properties=species:S:1:pos:R:3:fixed:L:1:tag:S:1:m:R:2 "
      "energy=-1.5 pbc=\"T T T\"\n"
      "2 0.0 0.0 0.0 T a 1 2\n"
      "1 1.0 1.5 2.0 F b 3 4\n"
      "2 3.9 4.9 5.9 F c 5 6\n";
  std::istringstream in(text);
  const auto frames = read_extxyz(in, "ase.xyz");
  ASSERT_EQ(frames.size(), 1u);
  const DumpFrame& f = frames[0];
  EXPECT_EQ(f.timestep, 0);  // no Timestep=: the frame's index
  EXPECT_EQ(f.ids(), (std::vector<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(f.types(), (std::vector<int>{2, 1, 2}));  // numeric species are the types
  EXPECT_FALSE(f.has("element"));
  EXPECT_EQ(f.column("fixed"), (std::vector<double>{1, 0, 0}));
  EXPECT_EQ(f.column("m[2]"), (std::vector<double>{2, 4, 6}));
  EXPECT_FALSE(f.has("tag"));
  EXPECT_EQ(f.box.hi, Vec3(4, 5, 6));
  EXPECT_EQ(f.box.lo, Vec3(0, 0, 0));
}

TEST(ExtXyzReader, NoLatticeIsShrinkWrappedAroundTheAtoms) {
  std::istringstream in("2\nmolecule\nH 0 0 0\nH 0.74 0 0\n");
  const auto f = read_extxyz(in, "h2.xyz").front();
  for (int d = 0; d < 3; ++d) EXPECT_EQ(f.box.boundary[d], geometry::Boundary::shrink);
  EXPECT_DOUBLE_EQ(f.box.lo.x(), -0.5);  // extent < 1 Å: widened by 0.5 Å each way
  EXPECT_DOUBLE_EQ(f.box.hi.x(), 1.24);
  EXPECT_EQ(f.element_names, (std::vector<std::string>{"H"}));
}

TEST(ExtXyzReader, BadInputNamesTheLine) {
  const std::string head = "Lattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:pos:R:3\n";
  expect_refused("2\n" + head + "Cu 0 0 0\n", "f.xyz:4: unexpected end of file, expected atom row 2 of 2");
  expect_refused("1\n" + head + "Cu 0 0\n", "f.xyz:3: expected 4 values per atom row");
  expect_refused("1\n" + head + "Cu 0 nan 0\n", "f.xyz:3: expected property column 'y' (a finite number), got 'nan'");
  expect_refused("two\n" + head, "f.xyz:1: expected the number of atoms");
  expect_refused("1\nLattice=\"4 1 0 0 4 0 0 0 4\"\nCu 0 0 0\n", "f.xyz:2: Lattice=\"4 1 0 0 4 0 0 0 4\" is a general triclinic cell");
  expect_refused("1\nLattice=\"4 0 0 3 4 0 0 0 4\"\nCu 0 0 0\n", "f.xyz:2: Lattice: tilt xy = 3 is beyond LAMMPS's limit");
  expect_refused("1\nLattice=\"4 0 0 1 4 0 0 0 4\" pbc=\"T F T\"\nCu 0 0 0\n", "needs a periodic y boundary");
  expect_refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=species:S:1:velo:R:3\nCu 0 0 0\n",
                 "f.xyz:2: Properties=\"species:S:1:velo:R:3\" has no pos:R:3");
  expect_refused("1\nLattice=\"4 0 0 0 4\"\nCu 0 0 0\n", "f.xyz:2: Lattice=\"4 0 0 0 4\": expected 9 numbers");
  expect_refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\" pbc=\"T T\"\nCu 0 0 0\n", "f.xyz:2: pbc=\"T T\"");
  expect_refused("1\npbc=\"T T T\"\nCu 0 0 0\n", "f.xyz:2: pbc has a periodic axis but the comment line has no Lattice");
  expect_refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\nCu 0 0 0\n", "f.xyz:2: the value of Lattice opens with \" but never closes");
  expect_refused("1\nProperties=species:S:1:pos:R\nCu 0 0 0\n", "f.xyz:2: Properties=\"species:S:1:pos:R\": expected name:type:count");
  expect_refused("1\n", "f.xyz:2: unexpected end of file, expected the comment line of frame 1");
  expect_refused("", "f.xyz: no extended XYZ frame found");
  expect_refused("1\nTimestep=1e3\nCu 0 0 0\n", "f.xyz:2: expected Timestep (an integer)");
}

}  // namespace
}  // namespace shockfield::io
