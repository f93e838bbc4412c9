// LAMMPS text dump reader and writer: a dump written by LAMMPS itself (fixtures/io/dump_fcc.in)
// is read and written back byte for byte; full-precision round trips; malformed input.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>
#include <random>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::io {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Expects read_dump on `text` to throw an InputError whose message contains `fragment`.
void expect_dump_error(const std::string& text, const std::string& fragment) {
  std::istringstream in(text);
  try {
    read_dump(in, "bad.dump");
    FAIL() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

const std::string header =
    "ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 1\n0 1\n0 1\n";

TEST(LammpsDump, ReadsLammpsOutput) {
  const auto frames = read_dump("fixtures/io/dump_fcc.lammpstrj");
  ASSERT_EQ(frames.size(), 2u);
  const DumpFrame& f = frames[0];
  EXPECT_EQ(f.timestep, 0);
  EXPECT_EQ(frames[1].timestep, 5);
  EXPECT_EQ(f.units, "metal");
  ASSERT_TRUE(f.time);
  EXPECT_EQ(*f.time, 0.0);
  EXPECT_EQ(f.natoms(), 32u);
  EXPECT_EQ(f.columns, (std::vector<std::string>{"id", "type", "x", "y", "z", "vx", "vy", "vz"}));
  EXPECT_EQ(f.bounds[2], "ff");
  EXPECT_EQ(f.box.boundary[0], geometry::Boundary::periodic);
  EXPECT_EQ(f.box.boundary[2], geometry::Boundary::fixed);
  EXPECT_DOUBLE_EQ(f.box.hi.x(), 7.23);
  EXPECT_EQ(f.ids()[1], 2);
  EXPECT_EQ(f.types()[1], 2);
  EXPECT_DOUBLE_EQ(f.positions()[1].x(), 1.8075);
  EXPECT_DOUBLE_EQ(f.column("vx")[0], -0.552178);
}

TEST(LammpsDump, WritesTheSameTextAsLammps) {
  const std::string path = "fixtures/io/dump_fcc.lammpstrj";
  std::ostringstream out;
  for (const auto& frame : read_dump(path)) write_dump_frame(out, frame);
  EXPECT_EQ(out.str(), slurp(path));
}

// LAMMPS writes a triclinic box as its bounding box and the tilts (Howto_triclinic); the box is
// the prism whose edges those give, and the writer prints the same header back.
TEST(LammpsDump, ReadsAndWritesTriclinicBoxesAsLammps) {
  const std::string path = "fixtures/io/dump_triclinic.lammpstrj";
  const auto frames = read_dump(path);
  ASSERT_EQ(frames.size(), 2u);
  const geometry::Box& box = frames[0].box;
  // region prism 0 3 0 2 0 2 1 -1 0.5 in lattice units of 3.615 Å
  EXPECT_DOUBLE_EQ(box.lo.x(), 0.0);
  EXPECT_DOUBLE_EQ(box.hi.x(), 3 * 3.615);
  EXPECT_DOUBLE_EQ(box.hi.y(), 2 * 3.615);
  EXPECT_EQ(box.tilt, Vec3(3.615, -3.615, 1.8075));
  // scaled positions xs ys zs give the same atoms as x y z (LAMMPS writes both; 2e-5 Å: xs ys zs
  // have the 6 significant digits of "%g", 5e-7 of cell edges up to 18 Å, summed over three)
  const auto& f = frames[1];
  for (std::size_t i = 0; i < f.natoms(); ++i) {
    const Vec3 x(f.column("x")[i], f.column("y")[i], f.column("z")[i]);
    const Vec3 s = f.box.from_fractional(Vec3(f.column("xs")[i], f.column("ys")[i], f.column("zs")[i]));
    EXPECT_LT((x - s).norm(), 2e-5) << i;
  }
  std::ostringstream out;
  for (const auto& frame : frames) write_dump_frame(out, frame);
  EXPECT_EQ(out.str(), slurp(path));
}

TEST(LammpsDump, FullPrecisionRoundTripThroughAFile) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  DumpFrame frame;
  frame.timestep = 123456789012;
  frame.box.lo = Vec3(-1.0 / 3.0, 0.1, -5.0);
  frame.box.hi = Vec3(10.0 / 3.0, 7.7, 5.0);
  frame.box.boundary[1] = geometry::Boundary::shrink;
  frame.bounds[1] = "ss";
  std::vector<double> id, x, c;
  for (int i = 0; i < 50; ++i) { id.push_back(i + 1); x.push_back(u(rng)); c.push_back(u(rng) * 1e-9); }
  frame.set_column("id", id);
  frame.set_column("x", x);
  frame.set_column("c_pe", c);
  const std::string file = shockfield::testing::scratch_path("roundtrip.dump").string();
  {
    DumpWriter w(file, {.full_precision = true});
    w.write(frame);
    frame.timestep += 1;
    w.write(frame);
  }
  const auto back = read_dump(file);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].timestep, 123456789013);
  EXPECT_EQ(back[0].columns, frame.columns);
  EXPECT_EQ(back[0].values, frame.values);
  EXPECT_EQ(back[0].box.lo, frame.box.lo);
  EXPECT_EQ(back[0].box.hi, frame.box.hi);
  EXPECT_EQ(back[0].box.boundary[1], geometry::Boundary::shrink);
}

TEST(LammpsDump, FrameFromAtoms) {
  md::Atoms atoms;
  atoms.mass = {1.0, 2.0};
  atoms.add(Vec3(0.5, 1.5, 2.5), 1, 7, Vec3(1, 2, 3));
  atoms.image[0] = {1, 0, -1};
  geometry::Box box;
  box.hi = Vec3(10, 10, 10);
  const DumpFrame f = make_dump_frame(3, box, atoms, {"id", "type", "xu", "zu", "iz", "vy", "mass"});
  EXPECT_EQ(f.column("id")[0], 7);
  EXPECT_EQ(f.column("type")[0], 2);
  EXPECT_EQ(f.column("xu")[0], 10.5);
  EXPECT_EQ(f.column("zu")[0], -7.5);
  EXPECT_EQ(f.column("iz")[0], -1);
  EXPECT_EQ(f.column("vy")[0], 2.0);
  EXPECT_EQ(f.column("mass")[0], 2.0);
  EXPECT_THROW(make_dump_frame(3, box, atoms, {"q"}), InputError);
}

// A dump LAMMPS wrote with an element column and the time (fixtures/io/dump_element.in:
// dump_modify element Cu Ni time yes) is read, names numbered in the order met, and written back
// byte for byte; a frame made from atoms names each type by atoms.type_names.
TEST(LammpsDump, ElementColumnAndTimeAsLammpsWritesThem) {
  const std::string path = "fixtures/io/dump_element.lammpstrj";
  const auto frames = read_dump(path);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].element_names, (std::vector<std::string>{"Cu", "Ni"}));
  EXPECT_EQ(frames[0].column("element")[1], 2.0);  // atom 2 is type 2, Ni
  EXPECT_EQ(frames[0].column("type")[1], 2.0);
  ASSERT_TRUE(frames[1].time);
  EXPECT_DOUBLE_EQ(*frames[1].time, 0.01);  // 5 steps of 2 fs
  std::ostringstream out;
  for (const auto& frame : frames) write_dump_frame(out, frame);
  EXPECT_EQ(out.str(), slurp(path));

  md::Atoms atoms;
  atoms.mass = {1.0, 2.0};
  atoms.type_names = {"Cu", "Ni"};
  atoms.add(Vec3(0.5, 1.5, 2.5), 1, 7);
  geometry::Box box;
  const DumpFrame f = make_dump_frame(3, box, atoms, {"id", "element", "x", "y", "z"});
  std::ostringstream one;
  write_dump_frame(one, f);
  EXPECT_NE(one.str().find("ITEM: ATOMS id element x y z\n7 Ni 0.5 1.5 2.5\n"), std::string::npos) << one.str();
  atoms.type_names = {"Cu", ""};
  EXPECT_THROW(make_dump_frame(3, box, atoms, {"element"}), InputError);  // type 2 has no name
}

// ITEM: TIME in the shortest text that reads back to the same double: 2000 MD steps of 0.001 ps
// summed give 1.9999999999998905, which LAMMPS's "%.16g" would print as 1.999999999999891 (another
// double) and 17 digits as 1.9999999999998905 only by luck of this value.
TEST(LammpsDump, TimeIsTheShortestTextThatReadsBack) {
  DumpFrame frame;
  frame.set_column("id", {1.0});
  double t = 0.0;
  for (int k = 0; k < 2000; ++k) t += 0.001;
  for (const double time : {t, 0.1 + 0.2, 2.0, 5.014800766619083e-05}) {
    frame.time = time;
    std::ostringstream out;
    write_dump_frame(out, frame);
    std::istringstream in(out.str());
    EXPECT_EQ(read_dump(in, "t.dump").at(0).time.value(), time) << out.str();
  }
  frame.time = t;
  std::ostringstream out;
  write_dump_frame(out, frame);
  EXPECT_NE(out.str().find("ITEM: TIME\n1.9999999999998905\n"), std::string::npos) << out.str();
  frame.time = 0.2;
  std::ostringstream short_text;
  write_dump_frame(short_text, frame);
  EXPECT_NE(short_text.str().find("ITEM: TIME\n0.2\n"), std::string::npos) << short_text.str();
}

TEST(LammpsDump, ScaledPositions) {
  std::istringstream in(header + "ITEM: ATOMS id xs ys zs\n1 0.5 0 1\n2 0.25 0.5 0\n");
  const auto f = read_dump(in, "s.dump").at(0);
  EXPECT_EQ(f.positions()[1], Vec3(0.25, 0.5, 0.0));
  EXPECT_THROW(f.column("x"), InputError);
}

TEST(LammpsDump, MalformedInput) {
  expect_dump_error("", "no dump frame");
  expect_dump_error(header + "ITEM: ATOMS id x y z\n1 0 0 0\n", "bad.dump:11: unexpected end of file, expected atom row 2 of 2");
  expect_dump_error(header + "ITEM: ATOMS id x y z\n1 0 0 0\n2 0 0\n", "bad.dump:11: expected 4 values");
  expect_dump_error(header + "ITEM: ATOMS id x y z\n1 0 0 0\n2 0 zero 0\n", "bad.dump:11: expected column 'y'");
  expect_dump_error(header + "ITEM: ATOMS id x x\n", "column 'x' appears twice");
  expect_dump_error(header + "ITEM: ATOMS\n", "expected column names");
  expect_dump_error("ITEM: TIMESTEP\n1\nITEM: NUMBER OF ATOMS\n0\nITEM: ATOMS id\n", "bad.dump:5: ITEM: ATOMS before");
  expect_dump_error("ITEM: TIMESTEP\nx\n", "bad.dump:2: expected the timestep");
  expect_dump_error("ITEM: TIMESTEP\n", "unexpected end of file, expected the timestep");
  expect_dump_error("ITEM: NUMBER OF ATOMS\n-3\n", "number of atoms >= 0");
  expect_dump_error("ITEM: BOX BOUNDS xy xz pp pp pp\n", "expected 'xy xz yz'");
  expect_dump_error("ITEM: BOX BOUNDS xy xz yz pp pp pp\n0 1\n", "bad.dump:2: expected 3 numbers 'xlo_bound xhi_bound xy'");
  // xy = 0.6 of lx = 1 (bounds 0..1.6): beyond LAMMPS's half
  expect_dump_error("ITEM: BOX BOUNDS xy xz yz pp pp pp\n0 1.6 0.6\n0 1 0\n0 1 0\n", "bad.dump:4: BOX BOUNDS: tilt xy = 0.6");
  expect_dump_error("ITEM: BOX BOUNDS xy xz yz pp pp pp\n0 1 3\n0 1 0\n0 1 0\n", "leave no room in the x bounds");
  expect_dump_error("ITEM: BOX BOUNDS pp pq pp\n", "boundary code");
  expect_dump_error("ITEM: BOX BOUNDS pp pp pp\n0 1\n2 1\n", "bad.dump:3: expected ylo < yhi");
  expect_dump_error("ITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n", "expected the zlo zhi line");
  expect_dump_error("ITEM: BONDS\n", "unknown section");
  expect_dump_error("1 2 3\n", "expected an 'ITEM:' line");
  expect_dump_error(header, "expected ITEM: ATOMS of timestep 7");
}

TEST(LammpsDump, MissingFile) { EXPECT_THROW(read_dump("fixtures/io/no_such.dump"), InputError); }

}  // namespace
}  // namespace shockfield::io
