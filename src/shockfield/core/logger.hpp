#pragma once
// Run log: every line goes to the run folder's log.txt and, unless quiet, to the terminal.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace shockfield {

class Logger {
 public:
  Logger() = default;
  /// Opens (or appends to) `file`; `echo` also prints each line to stdout.
  Logger(const std::filesystem::path& file, bool echo, bool append);

  void line(const std::string& text);
  template <class... Args>
  void info(fmt::format_string<Args...> format, Args&&... args) {
    line(fmt::format(format, std::forward<Args>(args)...));
  }

 private:
  std::ofstream file_;
  bool echo_ = true;
  bool terminal_ = false;
};

}  // namespace shockfield
