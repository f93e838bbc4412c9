#pragma once
// Run log: every line goes to the run folder's log.txt and, unless quiet, to the terminal.
// Writes to log.txt are checked (io::CheckedOutput): the first that fails throws RunError naming
// the file (exit 3); later lines go to the terminal only, so that reporting that failure (or
// another one) cannot fail again on the same file.
#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "shockfield/io/checked_file.hpp"

namespace shockfield {

class Logger {
 public:
  Logger() = default;
  /// Opens (or appends to) `file`; `echo` also prints each line to stdout. RunError naming the
  /// file when it cannot be opened.
  Logger(const std::filesystem::path& file, bool echo, bool append);

  void line(const std::string& text);
  template <class... Args>
  void info(fmt::format_string<Args...> format, Args&&... args) {
    line(fmt::format(format, std::forward<Args>(args)...));
  }

 private:
  io::CheckedOutput file_;
  bool echo_ = true;
  bool terminal_ = false;
};

}  // namespace shockfield
