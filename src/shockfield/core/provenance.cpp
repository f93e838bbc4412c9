#include "shockfield/core/provenance.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>

#include "shockfield/core/sha256.hpp"

// Set for this file only by CMakeLists.txt, so that a new commit recompiles nothing else.
#ifndef SHOCKFIELD_GIT_COMMIT
#define SHOCKFIELD_GIT_COMMIT "unknown"
#endif
#ifndef SHOCKFIELD_BUILD_TYPE
#define SHOCKFIELD_BUILD_TYPE "unknown"
#endif

namespace shockfield {

std::string iso8601_utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text.data();
}

std::string shell_command_line(const std::vector<std::string>& argv) {
  static constexpr std::string_view kSafe =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./:,@%";
  std::string out;
  for (const auto& arg : argv) {
    if (!out.empty()) out += ' ';
    if (!arg.empty() && arg.find_first_not_of(kSafe) == std::string::npos) {
      out += arg;
      continue;
    }
    out += '\'';
    for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

Provenance collect_provenance(const std::vector<std::string>& command_line,
                              const std::vector<std::filesystem::path>& input_files) {
  Provenance p;
  p.version = SHOCKFIELD_VERSION;
  p.git_commit = SHOCKFIELD_GIT_COMMIT;
  p.build_type = SHOCKFIELD_BUILD_TYPE;
  p.compiler = fmt::format("{} {}",
#if defined(__clang__)
                           "clang",
#elif defined(__GNUC__)
                           "gcc",
#else
                           "c++",
#endif
                           __VERSION__);
  std::array<char, 256> host{};
  p.host = gethostname(host.data(), host.size() - 1) == 0 ? host.data() : "unknown";
  p.command_line = shell_command_line(command_line);
  p.start_time = iso8601_utc_now();
  p.threads = omp_get_max_threads();
  for (const auto& file : input_files) {
    const auto absolute = std::filesystem::absolute(file).lexically_normal();
    p.input_files.push_back({absolute.string(), sha256_file_hex(absolute),
                             std::filesystem::file_size(absolute)});
  }
  return p;
}

toml::table provenance_toml(const Provenance& p) {
  toml::table t{{"version", p.version},       {"git_commit", p.git_commit},
                {"build_type", p.build_type}, {"compiler", p.compiler},
                {"host", p.host},             {"command_line", p.command_line},
                {"threads", p.threads},       {"start_time", p.start_time}};
  if (!p.end_time.empty()) t.insert("end_time", p.end_time);
  toml::array files;
  for (const auto& f : p.input_files)
    files.push_back(toml::table{{"path", f.path}, {"sha256", f.sha256},
                                {"bytes", static_cast<std::int64_t>(f.bytes)}});
  t.insert("input_files", std::move(files));
  return t;
}

std::vector<std::string> provenance_lines(const Provenance& p) {
  std::vector<std::string> lines{
      fmt::format("version: shockfield {} (git {}, {} build, {})", p.version, p.git_commit,
                  p.build_type, p.compiler),
      fmt::format("host: {}, {} OpenMP thread{}", p.host, p.threads, p.threads == 1 ? "" : "s"),
      fmt::format("command line: {}", p.command_line),
      fmt::format("start time: {}", p.start_time)};
  if (!p.end_time.empty()) lines.push_back(fmt::format("end time: {}", p.end_time));
  for (const auto& f : p.input_files)
    lines.push_back(fmt::format("input file: {} ({} bytes, sha256 {})", f.path, f.bytes, f.sha256));
  return lines;
}

}  // namespace shockfield
