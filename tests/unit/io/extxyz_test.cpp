// Extended XYZ writer: the comment line OVITO and ASE read, species from element names, vector
// properties grouped.
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

}  // namespace
}  // namespace shockfield::io
