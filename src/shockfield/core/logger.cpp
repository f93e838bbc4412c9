#include "shockfield/core/logger.hpp"

#include <unistd.h>

#include <cstdio>

#include "shockfield/core/error.hpp"

namespace shockfield {

Logger::Logger(const std::filesystem::path& file, bool echo, bool append)
    : file_(file, append ? std::ios::app : std::ios::trunc), echo_(echo), terminal_(isatty(STDOUT_FILENO) != 0) {}

void Logger::line(const std::string& text) {
  if (echo_) {
    if (terminal_) std::fputs("\r\033[K", stdout);  // over a progress line drawn in place
    std::fputs(text.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
  if (!file_.is_open()) return;
  try {
    file_.write(text);
    file_.write("\n");
    file_.flush();
  } catch (const RunError&) {
    file_ = io::CheckedOutput();  // closed: the next lines go to the terminal only
    throw;
  }
}

}  // namespace shockfield
