#include "shockfield/core/logger.hpp"

#include <cstdio>

namespace shockfield {

Logger::Logger(const std::filesystem::path& file, bool echo, bool append)
    : file_(file, append ? std::ios::app : std::ios::trunc), echo_(echo) {}

void Logger::line(const std::string& text) {
  if (file_.is_open()) file_ << text << '\n' << std::flush;
  if (echo_) {
    std::fputs(text.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
}

}  // namespace shockfield
