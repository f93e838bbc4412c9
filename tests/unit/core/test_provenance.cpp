// Provenance: input files recorded with absolute path, size and SHA-256; the program, build and
// machine fields filled; the command line quoted for a shell; the TOML table reads back.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>
#include <regex>

#include "shockfield/core/error.hpp"
#include "shockfield/core/provenance.hpp"

using namespace shockfield;

TEST(Provenance, RecordsInputFilesAndTheProgram) {
  const auto dir = shockfield::testing::scratch_path("shockfield_provenance");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "pot.eam") << "abc";
  const auto relative = std::filesystem::relative(dir / "pot.eam");
  const Provenance p = collect_provenance({"shockfield", "run", "case.toml"},
                                          {relative, dir / "sub" / ".." / "pot.eam"});
  ASSERT_EQ(p.input_files.size(), 2u);
  EXPECT_EQ(p.input_files[0].path, (dir / "pot.eam").string());  // absolute and normalised
  EXPECT_EQ(p.input_files[1].path, (dir / "pot.eam").string());
  EXPECT_EQ(p.input_files[0].bytes, 3u);
  EXPECT_EQ(p.input_files[0].sha256, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(p.version, SHOCKFIELD_VERSION);
  // A commit as CMake saw it: 40 hex digits, "+dirty" when the tree had changes, or "unknown".
  EXPECT_TRUE(std::regex_match(p.git_commit, std::regex("([0-9a-f]{40}(\\+dirty)?)|unknown"))) << p.git_commit;
  EXPECT_FALSE(p.build_type.empty());
  EXPECT_NE(p.compiler.find("gcc"), std::string::npos) << p.compiler;  // this project builds with GCC
  EXPECT_FALSE(p.host.empty());
  EXPECT_GE(p.threads, 1);
  EXPECT_TRUE(std::regex_match(p.start_time, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << p.start_time;
  EXPECT_TRUE(p.end_time.empty());
  EXPECT_EQ(p.command_line, "shockfield run case.toml");
  std::filesystem::remove_all(dir);
}

TEST(Provenance, MissingInputFileIsAnInputError) {
  EXPECT_THROW(collect_provenance({}, {shockfield::testing::scratch_path("shockfield_no_such_file")}),
               InputError);
}

TEST(Provenance, CommandLineIsQuotedForAShell) {
  EXPECT_EQ(shell_command_line({"shockfield", "run", "my case.toml", "--set", "a.b=\"x\"", "it's", ""}),
            "shockfield run 'my case.toml' --set 'a.b=\"x\"' 'it'\\''s' ''");
  EXPECT_EQ(shell_command_line({"--set", "md.dt=0.001", "-o", "/tmp/run_1"}), "--set md.dt=0.001 -o /tmp/run_1");
}

TEST(Provenance, TomlTableAndLogLines) {
  Provenance p;
  p.version = "0.1.0";
  p.git_commit = "abc+dirty";
  p.build_type = "Release";
  p.compiler = "gcc 12.2.0";
  p.host = "box";
  p.command_line = "shockfield run case.toml";
  p.start_time = "2026-12-01T20:00:00Z";
  p.threads = 2;
  p.input_files = {{"/data/Cu.eam", std::string(64, 'f'), 1234}};
  toml::table t = provenance_toml(p);
  EXPECT_FALSE(t.contains("end_time"));  // not yet known
  p.end_time = "2026-12-01T20:05:00Z";
  t = provenance_toml(p);
  EXPECT_EQ(t["git_commit"].value<std::string>(), "abc+dirty");
  EXPECT_EQ(t["threads"].value<int>(), 2);
  EXPECT_EQ(t["end_time"].value<std::string>(), "2026-12-01T20:05:00Z");
  EXPECT_EQ(t["input_files"][0]["path"].value<std::string>(), "/data/Cu.eam");
  EXPECT_EQ(t["input_files"][0]["bytes"].value<long long>(), 1234);
  const auto lines = provenance_lines(p);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "version: shockfield 0.1.0 (git abc+dirty, Release build, gcc 12.2.0)");
  EXPECT_EQ(lines[1], "host: box, 2 OpenMP threads");
  EXPECT_EQ(lines[5], "input file: /data/Cu.eam (1234 bytes, sha256 " + std::string(64, 'f') + ")");
}
