// Checked writes and verified checkpoints (io/checked_file, io/checkpoint_file): a write to a
// full device throws RunError naming the file; a checkpoint reads back what was written; one
// flipped payload byte, a truncation or a missing checksum is refused by name (InputError); a
// checkpoint that cannot be written leaves the previous one intact and no temporary file; 400
// one-byte mutants are each refused by name or read back intact; a stored count that is not a
// non-negative integer is refused; a checkpoint describes itself (method, format, version, the
// case and its SHA-256, units per dataset) and an older format or another method is refused by
// name.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/scratch_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "shockfield/core/error.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/checkpoint_file.hpp"
#include "shockfield/io/csv_writer.hpp"

namespace {

namespace fs = std::filesystem;
using namespace shockfield;

std::vector<char> bytes_of(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void put_bytes(const fs::path& f, const std::vector<char>& b) {
  std::ofstream(f, std::ios::binary | std::ios::trunc).write(b.data(), static_cast<std::streamsize>(b.size()));
}

// A payload whose bytes are easy to find in the file: 1.25, 2.25, ...
std::vector<double> marker_payload() {
  std::vector<double> v(64);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 1.25 + static_cast<double>(i);
  return v;
}

void write_sample(const fs::path& file, std::int64_t step) {
  io::CheckpointWriter w(file, "sample", 2);
  w.set_count("step", step);
  w.set_attribute("boundary", std::string("ppf"));
  w.write("x", "m", marker_payload(), {32, 2});
  w.write("id", "1", std::vector<std::int64_t>{7, 8, 9});
  w.commit();
}

template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct CheckpointFileTest : ::testing::Test {
  fs::path dir = shockfield::testing::scratch_path("checkpoint_file_test");
  fs::path file = dir / "checkpoint.h5";
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(CheckpointFileTest, ReadsBackWhatWasWrittenAndLeavesNoTemporary) {
  write_sample(file, 42);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  const io::CheckpointReader r(file);
  EXPECT_EQ(r.h5().attribute("step"), 42);
  EXPECT_EQ(r.h5().string_attribute("boundary"), "ppf");
  EXPECT_EQ(r.h5().read_doubles("x"), marker_payload());
  EXPECT_EQ(r.h5().read_ints("id"), (std::vector<std::int64_t>{7, 8, 9}));
}

TEST_F(CheckpointFileTest, OneFlippedPayloadByteIsRefusedByName) {
  write_sample(file, 1);
  auto b = bytes_of(file);
  const auto payload = marker_payload();
  const char* first = reinterpret_cast<const char*>(payload.data());
  const auto at = std::search(b.begin(), b.end(), first, first + payload.size() * sizeof(double));
  ASSERT_NE(at, b.end()) << "the payload is stored contiguously, uncompressed";
  at[100] ^= 0x01;  // one bit of one value in the middle of the dataset
  put_bytes(file, b);
  const std::string msg = input_error_of([&] { io::CheckpointReader r(file); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("damaged"), std::string::npos) << msg;
}

TEST_F(CheckpointFileTest, TruncatedCheckpointIsRefusedByName) {
  write_sample(file, 1);
  const auto size = fs::file_size(file);
  for (const auto keep : {size / 2, size - 1, std::uintmax_t{0}}) {
    write_sample(file, 1);
    fs::resize_file(file, keep);
    const std::string msg = input_error_of([&] { io::CheckpointReader r(file); });
    EXPECT_NE(msg.find(file.string()), std::string::npos) << "kept " << keep << " bytes: " << msg;
  }
}

TEST_F(CheckpointFileTest, CheckpointWithoutChecksumIsRefused) {
  {
    io::Hdf5File h5(file, io::Hdf5File::Mode::create);
    h5.set_attribute("step", 1.0);
    h5.close();
  }
  // A plain HDF5 file (no trailer): refused before libhdf5 parses it.
  std::string msg = input_error_of([&] { io::CheckpointReader r(file); });
  EXPECT_NE(msg.find("no whole-file checksum trailer"), std::string::npos) << msg;
  // With a correct trailer appended (FNV-1a 64 of the bytes) but no item checksum inside.
  const std::vector<char> bytes = bytes_of(file);
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  std::ofstream(file, std::ios::binary | std::ios::app) << fmt::format("\nshockfield checkpoint fnv1a64 {:016x}\n", hash);
  msg = input_error_of([&] { io::CheckpointReader r(file); });
  EXPECT_NE(msg.find("no checksum"), std::string::npos) << msg;
}

// A byte changed inside the HDF5 image is caught by the trailer, before libhdf5 reads the file.
TEST_F(CheckpointFileTest, WholeFileChecksumIsCheckedFirst) {
  write_sample(file, 1);
  std::vector<char> bytes = bytes_of(file);
  bytes[bytes.size() / 3] ^= 0x5a;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const std::string msg = input_error_of([&] { io::CheckpointReader r(file); });
  EXPECT_NE(msg.find("whole-file checksum"), std::string::npos) << msg;
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
}

TEST_F(CheckpointFileTest, FailedWriteKeepsThePreviousCheckpoint) {
  write_sample(file, 1);
  const auto before = bytes_of(file);
  // A folder in the way of the temporary file makes its creation fail (as root too).
  fs::create_directories(file.string() + ".tmp");
  try {
    write_sample(file, 2);
    FAIL() << "the write should have failed";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("previous checkpoint is kept"), std::string::npos) << e.what();
  }
  EXPECT_EQ(bytes_of(file), before);
  EXPECT_EQ(io::CheckpointReader(file).h5().attribute("step"), 1);
}

TEST_F(CheckpointFileTest, CountsAreNonNegativeIntegers) {
  // Counters are stored as integers; one stored as a real (as before format bumps of
  // 2026-12-03, NaN or 1e300 included) or a negative one is refused by name.
  write_sample(file, 42);
  EXPECT_EQ(io::CheckpointReader(file).count("step"), 42);
  write_sample(file, -1);
  std::string msg = input_error_of([&] { io::CheckpointReader(file).count("step"); });
  EXPECT_NE(msg.find("'step' = -1 is not a count"), std::string::npos) << msg;
  for (const double bad : {std::nan(""), 1e300, 2.0}) {
    io::CheckpointWriter w(file, "sample", 2);
    w.set_attribute("step", bad);
    w.commit();
    msg = input_error_of([&] { io::CheckpointReader(file).count("step"); });
    EXPECT_NE(msg.find(file.string()), std::string::npos) << bad << ": " << msg;
    EXPECT_NE(msg.find("'step' is not stored as an integer"), std::string::npos) << bad << ": " << msg;
  }
}

TEST_F(CheckpointFileTest, DescribesItselfAndRefusesAnotherMethodOrFormatByName) {
  const std::string resolved = "method = 'sample'\n[sample]\nsteps = 3\n";
  const std::string input = "method = 'sample'\n";
  {
    const io::CheckpointCaseScope scope({resolved, input});
    write_sample(file, 3);
  }
  const io::CheckpointReader r(file);
  const io::Hdf5File& h5 = r.h5();
  EXPECT_EQ(h5.string_attribute("format"), "shockfield checkpoint");
  EXPECT_EQ(r.method(), "sample");
  EXPECT_EQ(h5.int_attribute("format_version"), 2);
  EXPECT_EQ(h5.string_attribute("shockfield_version"), shockfield_version());
  EXPECT_EQ(h5.string_attribute("git_commit"), shockfield_git_commit());
  EXPECT_EQ(h5.string_attribute("case"), resolved);
  EXPECT_EQ(h5.string_attribute("case_sha256"), sha256_hex(resolved));
  EXPECT_EQ(r.input_case(), input);
  EXPECT_EQ(h5.dataset_names(), (std::vector<std::string>{"id", "x"}));
  EXPECT_EQ(h5.units("x"), "m");
  EXPECT_EQ(h5.units("id"), "1");
  EXPECT_EQ(h5.shape("x"), (std::vector<hsize_t>{32, 2}));
  EXPECT_NO_THROW(r.require("sample", 2));
  std::string msg = input_error_of([&] { r.require("sample", 3); });
  EXPECT_NE(msg.find("sample checkpoint format 2 is older than the supported 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  msg = input_error_of([&] { r.require("sample", 1); });
  EXPECT_NE(msg.find("format 2 is newer than the supported 1"), std::string::npos) << msg;
  msg = input_error_of([&] { r.require("mpm", 2); });
  EXPECT_NE(msg.find("a sample checkpoint, not a mpm one"), std::string::npos) << msg;
  // Outside a run (no scope) the cases are empty, and --resume's reading of the input case refuses
  // by name.
  write_sample(file, 3);
  EXPECT_EQ(io::CheckpointReader(file).h5().string_attribute("case"), "");
  msg = input_error_of([&] { io::CheckpointReader(file).input_case(); });
  EXPECT_NE(msg.find("does not hold the case it was written with"), std::string::npos) << msg;
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
}

TEST_F(CheckpointFileTest, EveryOneByteMutantIsReadWholeOrRefusedByName) {
  // 400 mutants (deterministic: offsets and values from a fixed LCG), each one byte of the file
  // replaced: the reader must either refuse it by name (InputError) or return exactly what was
  // written (the byte was padding or unused metadata); never a crash, a hang or other contents.
  write_sample(file, 3);
  const auto good = bytes_of(file);
  std::uint64_t state = 2026;
  auto next = [&] { return state = state * 6364136223846793005ull + 1442695040888963407ull, state >> 33; };
  int refused = 0, intact = 0;
  for (int k = 0; k < 400; ++k) {
    auto b = good;
    const std::size_t at = next() % b.size();
    const auto value = static_cast<char>(next() & 0xff);
    if (b[at] == value) continue;
    b[at] = value;
    put_bytes(file, b);
    try {
      const io::CheckpointReader r(file);
      EXPECT_EQ(r.h5().int_attribute("step"), 3) << "byte " << at;
      EXPECT_EQ(r.h5().read_doubles("x"), marker_payload()) << "byte " << at;
      EXPECT_EQ(r.h5().read_ints("id"), (std::vector<std::int64_t>{7, 8, 9})) << "byte " << at;
      ++intact;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
  std::printf("checkpoint mutants: %d refused by name, %d read back intact\n", refused, intact);
}

TEST(CheckedOutput, FullDeviceThrowsRunErrorNamingTheFile) {
  io::CheckedOutput out("/dev/full");
  out << std::string(100000, 'x');  // more than the stream buffer
  try {
    out.close();
    FAIL() << "writing to /dev/full must fail";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
}

TEST(CheckedOutput, CsvWriterOnAFullDeviceThrows) {
  EXPECT_THROW(io::CsvWriter("/dev/full", {"t", "x"}), RunError);
}

TEST(PayloadChecksum, EqualItemsGiveEqualSumsAndOneUlpChangesIt) {
  io::PayloadChecksum a, b, c;
  const double x = 1.0, y = std::nextafter(1.0, 2.0);
  a.add('f', "t", &x, sizeof x);
  b.add('f', "t", &x, sizeof x);
  c.add('f', "t", &y, sizeof y);
  EXPECT_EQ(a.hex(), b.hex());
  EXPECT_NE(a.hex(), c.hex());
  EXPECT_EQ(a.hex().size(), 16u);
}

}  // namespace
