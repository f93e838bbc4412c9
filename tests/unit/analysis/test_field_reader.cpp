// Field reader: the same 4 x 3 x 2 field (value x + 10 y + 100 z, one void cell) in every format
// (fixtures/analysis/fields, written by fixtures/analysis/make_field_fixtures.py), .pvd series and
// run folders, and malformed files giving file:line messages.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/core/error.hpp"

namespace sa = shockfield::analysis;
namespace fs = std::filesystem;

namespace {

const std::string kDir = "fixtures/analysis/fields/";

// The fixture field; `void_cell`: cell (1, 2, 1) is void (else it holds 0, as in binary.vti).
void expect_fixture(const sa::GridField& f, bool void_cell = true) {
  ASSERT_EQ(f.n, (std::array<std::size_t, 3>{4, 3, 2}));
  EXPECT_EQ(f.spacing, (std::array<double, 3>{0.5, 0.5, 0.5}));
  EXPECT_EQ(f.origin, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(f.void_count(), void_cell ? 1u : 0u);
  for (std::size_t z = 0; z < 2; ++z)
    for (std::size_t y = 0; y < 3; ++y)
      for (std::size_t x = 0; x < 4; ++x) {
        const std::size_t i = f.index(x, y, z);
        if (x == 1 && y == 2 && z == 1) {
          EXPECT_EQ(f.void_at(i), void_cell);
          if (!void_cell) {
            EXPECT_EQ(f.values[i], 0.0);
          }
          continue;
        }
        EXPECT_EQ(f.values[i], double(x + 10 * y + 100 * z)) << x << " " << y << " " << z;
      }
}

// Writes `text` to a file named `name` in a fresh temporary folder and returns its path.
std::string write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = shockfield::testing::scratch_path("sf_reader");
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return (dir / name).string();
}

void expect_error(const std::string& path, const std::string& fragment) {
  try {
    sa::read_grid_field(path);
    ADD_FAILURE() << path << ": no InputError; expected one mentioning '" << fragment << "'";
  } catch (const shockfield::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

const std::string kLegacyHead =
    "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 1\n";

// A VTK XML image of 2 x 2 points whose one array T has the given type, format and content.
std::string vti_array(const std::string& type, const std::string& format,
                      const std::string& content, const std::string& file_attributes = "") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" byte_order=\"LittleEndian\"" +
         file_attributes + ">\n<ImageData WholeExtent=\"0 1 0 1 0 0\">\n<PointData>\n" +
         "<DataArray type=\"" + type + "\" Name=\"T\" format=\"" + format + "\"" + content +
         "\n</PointData>\n</ImageData>\n</VTKFile>\n";
}

}  // namespace

TEST(FieldReader, EveryFormatGivesTheSameField) {
  for (const char* file : {"grid.csv", "cells.vtk", "ascii.vti", "appended_base64.vti"}) {
    SCOPED_TRACE(file);
    expect_fixture(sa::read_grid_field(kDir + file));
  }
  expect_fixture(sa::read_grid_field(kDir + "points.vtk", "T"));
  expect_fixture(sa::read_grid_field(kDir + "raw.vti", "T"));
  expect_fixture(sa::read_grid_field(kDir + "binary.vti"), false);  // big-endian Int32, base64
  // Written by VTK 9.1 with zlib compression (make_field_fixtures.py): UInt32 headers, inline
  // base64 (header and data encoded separately) and appended raw.
  expect_fixture(sa::read_grid_field(kDir + "vtk_zlib_binary.vti"));
  expect_fixture(sa::read_grid_field(kDir + "vtk_zlib_appended.vti"));
}

TEST(FieldReader, DefaultArrayIsTheFirstScalarOne) {
  for (const char* file : {"points.vtk", "raw.vti"}) {  // "zero" comes first
    const auto f = sa::read_grid_field(kDir + file);
    EXPECT_EQ(f.values, std::vector<double>(24, 0.0)) << file;
  }
  expect_fixture(sa::read_grid_field(kDir + "ascii.vti"));  // the 3-component "u" is skipped
  try {
    sa::read_grid_field(kDir + "ascii.vti", "u");
    ADD_FAILURE() << "a vector array was read as a scalar field";
  } catch (const shockfield::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ascii.vti:6: DataArray 'u' has 3 components"),
              std::string::npos)
        << e.what();
  }
}

TEST(FieldReader, SeriesInTimeOrderFromPvdOrRunFolder) {
  for (const std::string& path : {kDir + "series.pvd", kDir}) {
    const auto s = sa::read_series(path);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].time, 0.25);
    EXPECT_EQ(fs::path(s[0].file).filename(), "appended_base64.vti");
    EXPECT_EQ(s[1].time, 0.5);
    expect_fixture(sa::read_grid_field(s[1].file));
  }
  const fs::path empty = fs::path(write_temp("x.csv", "1")).parent_path();
  EXPECT_THROW(sa::read_series(empty.string()), shockfield::InputError);
}

TEST(FieldReader, MalformedCsvNamesFileAndLine) {
  expect_error(write_temp("rows.csv", "1,2,3\n4,5,6\n7,8\n"),
               "rows.csv:3: 2 values in this row, 3");
  expect_error(write_temp("word.csv", "# spacing = 1\n1,abc\n"),
               "word.csv:2: 'abc' is not a number");
  expect_error(write_temp("nan.csv", "1,2\nnan,3\n"), "nan.csv:2: NaN value; write `void`");
  expect_error(write_temp("slices.csv", "1,2\n3,4\n\n5,6\n"), "slices.csv:4: slice 2 has 1 rows");
  expect_error(write_temp("spacing.csv", "# spacing = wide\n1\n"), "spacing.csv:1: 'wide'");
  expect_error(write_temp("empty.csv", "# nothing\n"), "empty field");
  expect_error(write_temp("inf.csv", "1,inf\n"), "inf.csv:1: 'inf' is infinite; expected a finite number");
}

TEST(FieldReader, MalformedLegacyVtkNamesFileAndLine) {
  expect_error(write_temp("bin.vtk", "# vtk DataFile Version 3.0\nt\nBINARY\n"),
               "bin.vtk:3: legacy VTK encoding 'BINARY'");
  expect_error(write_temp("head.vtk", "hello\n"), "head.vtk:1: not a legacy VTK file");
  const std::string scalars =
      kLegacyHead + "POINT_DATA 4\nSCALARS T double\nLOOKUP_TABLE default\n";
  expect_error(write_temp("short.vtk", scalars + "1 2\n3\n"),
               "short.vtk:10: 4 values expected for 2 x 2 x 1 cells, the data ends after 3");
  expect_error(write_temp("word.vtk", scalars + "1 2\n3 x\n"), "word.vtk:10: 'x' is not a number");
  expect_error(write_temp("count.vtk", kLegacyHead + "POINT_DATA 5\n"),
               "count.vtk:6: point_data 5 for DIMENSIONS 2 2 1; expected 4");
  expect_error(write_temp("grid.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n"),
               "grid.vtk:4: DATASET POLYDATA; expected STRUCTURED_POINTS");
  expect_error(write_temp("none.vtk", kLegacyHead), "none.vtk: no SCALARS array");
}

TEST(FieldReader, MalformedVtiNamesFileAndLine) {
  expect_error(kDir + "compressed_lz4.vti", "is compressed with vtkLZ4DataCompressor; only vtkZLibDataCompressor");
  expect_error(kDir + "compressed.vti", "DataArray 'T': the compressed data ends in its header");
  struct Case {
    const char *file, *type, *format, *content, *message;
  };
  // binary: base64 of a UInt32 header, then Float64 values (IAAAAA: 32 bytes, EAAAAA: 16).
  for (const Case& c : std::initializer_list<Case>{
           {"ascii.vti", "Float64", "ascii", ">\n1 2\n3 z\n</DataArray>",
            "ascii.vti:7: 'z' is not a number"},
           {"short.vti", "Float64", "binary", ">IAAAAAAAAAAAAPA/</DataArray>",
            "short.vti:5: DataArray 'T': 32 bytes expected, the data ends after 8"},
           {"header.vti", "Float64", "binary", ">EAAAAA==</DataArray>",
            "the header says 16 bytes; expected 32 (4 values of Float64)"},
           {"chars.vti", "Float64", "binary", ">IAA*</DataArray>", "'*' is not a base64 character"},
           {"type.vti", "Complex", "binary", ">IAAAAA==</DataArray>", "type=\"Complex\""},
           {"noappend.vti", "Float64", "appended", " offset=\"0\"/>", "no <AppendedData>"}})
    expect_error(write_temp(c.file, vti_array(c.type, c.format, c.content)), c.message);
  expect_error(write_temp("extent.vti", "<VTKFile>\n<ImageData WholeExtent=\"0 1\">"),
               "extent.vti:2: WholeExtent value expected");
  expect_error(write_temp("x.vti", "<VTKFile/>\n"), "no <ImageData> element");
  expect_error(write_temp("x.dat", "1\n"), "unknown field format '.dat'");
  expect_error("no/such/file.csv", "no/such/file.csv: cannot open");
}
