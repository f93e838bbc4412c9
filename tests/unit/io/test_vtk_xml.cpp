// VTK XML writers: base64 against RFC 4648 vectors; a .vti written in every encoding and
// precision reads back through analysis/field_reader with NaN points as void cells; the zlib
// block layout of VTK; .pvd entries survive a resume up to its time.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/io/vtk_zlib.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

std::string b64(const std::string& s) { return io::base64(reinterpret_cast<const unsigned char*>(s.data()), s.size()); }

// An empty scratch folder for one test's files.
fs::path fresh_dir(const char* name) {
  const fs::path dir = shockfield::testing::scratch_path(name);
  fs::create_directories(dir);
  return dir;
}

TEST(VtkXml, Base64Rfc4648Vectors) {
  EXPECT_EQ(b64(""), "");
  EXPECT_EQ(b64("f"), "Zg==");
  EXPECT_EQ(b64("fo"), "Zm8=");
  EXPECT_EQ(b64("foo"), "Zm9v");
  EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
}

TEST(VtkXml, ImageDataReadsBackWithVoids) {
  const fs::path dir = fresh_dir("shockfield_vtk_xml_test");
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

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every encoding and precision: the values read back exactly (Float64) or as the nearest float
// (Float32, so 310.1 reads as 310.100006…), NaN stays a void, units are in the tags.
TEST(VtkXml, EveryEncodingAndPrecisionReadsBack) {
  const fs::path dir = fresh_dir("shockfield_vtk_formats_test");
  io::VtkImage img;
  img.points = {40, 30, 1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t(1200);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 300.0 + 0.1 * static_cast<double>(i % 97) + 1e-9 * static_cast<double>(i);
  t[7] = nan;
  img.point_data.push_back({"temperature", 1, t, "K"});
  img.point_data.push_back({"velocity", 3, std::vector<double>(3600, -2.5), "m/s"});
  for (io::VtkEncoding e : {io::VtkEncoding::Ascii, io::VtkEncoding::Base64, io::VtkEncoding::Raw, io::VtkEncoding::Zlib})
    for (io::VtkPrecision p : {io::VtkPrecision::Float64, io::VtkPrecision::Float32}) {
      const std::string name = fmt::format("{}_{}.vti", io::encoding_name(e), p == io::VtkPrecision::Float32 ? 32 : 64);
      io::write_vti(dir / name, img, {e, p});
      const std::string text = read_text(dir / name);
      EXPECT_NE(text.find("Name=\"temperature\" NumberOfComponents=\"1\""), std::string::npos) << name;
      EXPECT_NE(text.find("units=\"K\""), std::string::npos) << name;
      EXPECT_EQ(text.find("compressor=") != std::string::npos, e == io::VtkEncoding::Zlib) << name;
      const analysis::GridField f = analysis::read_grid_field((dir / name).string(), "temperature");
      ASSERT_EQ(f.values.size(), t.size()) << name;
      for (std::size_t i = 0; i < t.size(); ++i) {
        if (i == 7) {
          EXPECT_TRUE(f.void_at(i)) << name;
          continue;
        }
        const float single = static_cast<float>(t[i]);  // ascii holds the float's shortest text
        const double expected = p == io::VtkPrecision::Float64 ? t[i]
                                : e == io::VtkEncoding::Ascii  ? std::stod(fmt::format("{}", single))
                                                               : static_cast<double>(single);
        ASSERT_EQ(f.values[i], expected) << name << " value " << i;
      }
    }
  // A slowly varying field compresses: zlib Float32 at least 4x smaller than ascii Float64.
  const auto size = [&](const char* n) { return static_cast<double>(fs::file_size(dir / n)); };
  EXPECT_GT(size("ascii_64.vti") / size("zlib_32.vti"), 4.0);
  fs::remove_all(dir);
}

// Categorical arrays (material, body, grain) are Int32 in every precision, their values exact.
TEST(VtkXml, CategoricalArraysAreInt32) {
  const fs::path dir = fresh_dir("shockfield_vtk_labels_test");
  const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 2, 0, 0};
  for (io::VtkPrecision p : {io::VtkPrecision::Float64, io::VtkPrecision::Float32}) {
    io::write_vtp(dir / "labels.vtp", xyz, {{"grain", 1, {3, 0, 70000}, "1", true}, {"damage", 1, {0.5, 0, 1}, "1"}},
                  {io::VtkEncoding::Ascii, p});
    const std::string text = read_text(dir / "labels.vtp");
    EXPECT_NE(text.find("type=\"Int32\" Name=\"grain\""), std::string::npos) << text;
    EXPECT_NE(text.find("3 0 70000\n"), std::string::npos) << text;
    EXPECT_EQ(text.find("type=\"Int32\" Name=\"damage\""), std::string::npos) << text;
  }
  fs::remove_all(dir);
}

// Points without material: VTK's blanking array after the data arrays (so `analyze`, which reads
// the first scalar array by default, still finds the data), 2 = HIDDENPOINT where hidden.
TEST(VtkXml, HiddenPointsAreVtkGhostType) {
  const fs::path dir = fresh_dir("shockfield_vtk_ghost_test");
  io::VtkImage img;
  img.points = {3, 2, 1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  img.point_data.push_back({"density", 1, {1, nan, 3, 4, 5, nan}, "kg/m3"});
  img.hidden_points = {false, true, false, false, false, true};
  io::write_vti(dir / "ghost.vti", img, {io::VtkEncoding::Ascii});
  const std::string text = read_text(dir / "ghost.vti");
  const auto ghost = text.find("type=\"UInt8\" Name=\"vtkGhostType\"");
  ASSERT_NE(ghost, std::string::npos) << text;
  EXPECT_GT(ghost, text.find("Name=\"density\""));
  EXPECT_NE(text.find("0 2 0 0 0 2\n"), std::string::npos) << text;
  const analysis::GridField f = analysis::read_grid_field((dir / "ghost.vti").string());
  EXPECT_TRUE(f.void_at(1) && f.void_at(5) && !f.void_at(0));
  EXPECT_EQ(f.values[2], 3.0);
  img.hidden_points.pop_back();
  EXPECT_THROW(io::write_vti(dir / "bad.vti", img, {io::VtkEncoding::Ascii}), shockfield::RunError);
  fs::remove_all(dir);
}

// VTK's compressed-array layout: [blocks, block size, last block size, compressed sizes...],
// a partial last block, and a full last block written as 0.
TEST(VtkXml, ZlibBlocksFollowVtkLayout) {
  std::vector<unsigned char> data(2500);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<unsigned char>(i * 7 % 251);
  for (std::size_t total : {std::size_t{2500}, std::size_t{2000}, std::size_t{0}}) {
    const std::string packed = io::vtk_zlib_compress(data.data(), total, 1000);
    std::uint64_t header[3];
    std::memcpy(header, packed.data(), sizeof header);
    EXPECT_EQ(header[0], (total + 999) / 1000);
    EXPECT_EQ(header[1], 1000u);
    EXPECT_EQ(header[2], total % 1000);
    std::size_t pos = 0;
    const auto take = [&](std::size_t n) {
      const std::string out = packed.substr(std::min(pos, packed.size()), n);
      pos += out.size();
      return out;
    };
    const auto same = [](std::string b) { return b; };
    const std::string plain = io::vtk_zlib_decompress(take, 8, same, total, "test");
    ASSERT_EQ(plain.size(), total);
    EXPECT_EQ(std::memcmp(plain.data(), data.data(), total), 0);
  }
}

// A compressed array that lies: a wrong total, a truncated block, a corrupt block.
TEST(VtkXml, CorruptZlibDataIsAnInputError) {
  std::vector<double> v(1000, 1.5);
  const std::string packed = io::vtk_zlib_compress(v.data(), 8000, 4096);
  const auto reader = [](const std::string& bytes) {
    return [bytes, pos = std::size_t{0}](std::size_t n) mutable {
      const std::string out = bytes.substr(std::min(pos, bytes.size()), n);
      pos += out.size();
      return out;
    };
  };
  const auto same = [](std::string b) { return b; };
  EXPECT_THROW(io::vtk_zlib_decompress(reader(packed), 8, same, 8008, "f"), InputError);
  EXPECT_THROW(io::vtk_zlib_decompress(reader(packed.substr(0, packed.size() - 3)), 8, same, 8000, "f"), InputError);
  std::string corrupt = packed;
  corrupt[5 * 8 + 2] ^= 0x5a;  // inside the first compressed block
  EXPECT_THROW(io::vtk_zlib_decompress(reader(corrupt), 8, same, 8000, "f"), InputError);
  EXPECT_THROW(io::vtk_zlib_decompress(reader(packed.substr(0, 12)), 8, same, 8000, "f"), InputError);
  EXPECT_EQ(io::vtk_zlib_decompress(reader(packed), 8, same, 8000, "f").size(), 8000u);
}

TEST(VtkXml, PvdSeriesKeepsEntriesUpToTheResumeTime) {
  const fs::path dir = fresh_dir("shockfield_pvd_test");
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
