// VTK XML writers: base64 against RFC 4648 vectors; a .vti written as ASCII reads back through
// analysis/field_reader with NaN points as void cells; .pvd entries survive a resume up to its time.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

std::string b64(const std::string& s) { return io::base64(reinterpret_cast<const unsigned char*>(s.data()), s.size()); }

TEST(VtkXml, Base64Rfc4648Vectors) {
  EXPECT_EQ(b64(""), "");
  EXPECT_EQ(b64("f"), "Zg==");
  EXPECT_EQ(b64("fo"), "Zm8=");
  EXPECT_EQ(b64("foo"), "Zm9v");
  EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
}

TEST(VtkXml, ImageDataReadsBackWithVoids) {
  const fs::path dir = shockfield::testing::scratch_path("shockfield_vtk_xml_test");
  fs::create_directories(dir);
  io::VtkImage img;
  img.points = {3, 2, 1};
  img.origin = {1.0, 2.0, 0.0};
  img.spacing = {0.5, 0.25, 1.0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  img.point_data.push_back({"temperature", 1, {300, 310.5, 320, nan, 1e-7, -2.5}});
  img.point_data.push_back({"velocity", 3, std::vector<double>(18, 1.0)});
  io::write_vti(dir / "f.vti", img, io::VtkEncoding::Ascii);
  const analysis::GridField f = analysis::read_grid_field((dir / "f.vti").string(), "temperature");
  EXPECT_EQ(f.n[0], 3u);
  EXPECT_EQ(f.n[1], 2u);
  EXPECT_EQ(f.n[2], 1u);
  EXPECT_DOUBLE_EQ(f.spacing[1], 0.25);
  EXPECT_DOUBLE_EQ(f.origin[0], 1.0);
  EXPECT_DOUBLE_EQ(f.values[1], 310.5);
  EXPECT_DOUBLE_EQ(f.values[5], -2.5);
  EXPECT_TRUE(f.void_at(3));
  EXPECT_FALSE(f.void_at(4));

  io::write_vti(dir / "b.vti", img, io::VtkEncoding::Base64);
  std::ifstream in(dir / "b.vti");
  std::stringstream text;
  text << in.rdbuf();
  // 6 doubles = 48 bytes: header "MAAAAAAAAAA=" (UInt64 48), then 64 base64 characters of data.
  EXPECT_NE(text.str().find("format=\"binary\">\nMAAAAAAAAAA="), std::string::npos);
  fs::remove_all(dir);
}

TEST(VtkXml, PvdSeriesKeepsEntriesUpToTheResumeTime) {
  const fs::path dir = shockfield::testing::scratch_path("shockfield_pvd_test");
  fs::create_directories(dir);
  {
    io::PvdSeries s(dir / "a.pvd");
    s.add(0.0, "f0.vti");
    s.add(1e-9, "f1.vti");
    s.add(2e-9, "f2.vti");
  }
  const double keep = 1e-9;
  io::PvdSeries resumed(dir / "a.pvd", &keep);
  EXPECT_EQ(resumed.size(), 2u);
  resumed.add(3e-9, "f3.vti");
  std::ifstream in(dir / "a.pvd");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().find("f2.vti"), std::string::npos);
  EXPECT_NE(text.str().find("file=\"f3.vti\""), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
