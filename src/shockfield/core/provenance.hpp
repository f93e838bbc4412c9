#pragma once
// Where a run came from: the program (version, git commit, build type, compiler), the machine
// (host, threads), the command line, the start and end times, and every potential, material and
// data file the case read (absolute path, SHA-256, size). Written to log.txt, to
// config.resolved.toml as [provenance] and to summary.json.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace shockfield {

struct InputFileRecord {
  std::string path;    ///< absolute
  std::string sha256;  ///< 64 hex digits
  std::uintmax_t bytes = 0;
};

struct Provenance {
  std::string version, git_commit, build_type, compiler, host, command_line, start_time, end_time;  ///< times ISO 8601 UTC
  int threads = 0;  ///< OpenMP threads the run uses
  std::vector<InputFileRecord> input_files;
};

/// The provenance of a run starting now: start_time is now, end_time empty (the driver sets it).
/// The git commit is the one CMake saw at configure time ("+dirty" when the tree had changes,
/// "unknown" outside a checkout). Input files are hashed here; an unreadable one is an InputError.
Provenance collect_provenance(const std::vector<std::string>& command_line,
                              const std::vector<std::filesystem::path>& input_files);

/// This build's version and the git commit CMake saw at configure time (as in Provenance).
std::string shockfield_version();
std::string shockfield_git_commit();

/// The current time as ISO 8601 UTC to the second, e.g. "2026-12-01T20:50:07Z".
std::string iso8601_utc_now();

/// argv joined with spaces, each argument that a POSIX shell would split or expand single-quoted,
/// so the line can be pasted back into a shell.
std::string shell_command_line(const std::vector<std::string>& argv);

/// [provenance]: the fields as keys (end_time only once set) and input_files as an array of
/// tables {path, sha256, bytes}.
toml::table provenance_toml(const Provenance& provenance);

/// One "name: value" line per field and one per input file, for log.txt.
std::vector<std::string> provenance_lines(const Provenance& provenance);

}  // namespace shockfield
