#include "shockfield/io/checked_file.hpp"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "shockfield/core/error.hpp"

namespace shockfield::io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const char* what, int error) {
  // A stream whose failing write left no errno: a full file system is the usual cause, say so
  // when it is the case.
  struct statvfs fs {};
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
  if (!error && ::statvfs(folder.c_str(), &fs) == 0 && fs.f_bavail == 0) error = ENOSPC;
  throw RunError(fmt::format("{}: {} failed: {}", file.string(), what,
                             error ? std::strerror(error) : "the stream reported an error"));
}

}  // namespace

CheckedOutput::CheckedOutput(const std::filesystem::path& file, std::ios::openmode mode) : file_(file) {
  errno = 0;
  out_.open(file, std::ios::out | mode);
  if (!out_) fail(file_, "opening for writing", errno);
}

void CheckedOutput::note_error() {
  if (!out_ && !error_) error_ = errno;
}

void CheckedOutput::check(const char* what) {
  note_error();
  if (!out_) fail(file_, what, error_);
}

void CheckedOutput::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  check("writing");
}

void CheckedOutput::flush() {
  out_.flush();
  check("writing");
}

void CheckedOutput::close() {
  if (!out_.is_open()) return;
  flush();
  out_.close();
  check("closing");
}

void write_file_checked(const std::filesystem::path& file, std::span<const std::string_view> parts, bool sync) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(file, "opening for writing", errno);
  auto give_up = [&](const char* what) {
    const int error = errno;
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(file, ignored);  // a partial file must not be mistaken for a whole one
    fail(file, what, error);
  };
  for (const std::string_view bytes : parts)
    for (std::size_t done = 0; done < bytes.size();) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) give_up("writing");
      done += static_cast<std::size_t>(n);
    }
  if (sync && ::fsync(fd) != 0) give_up("fsync");
  if (::close(fd) != 0) {
    const int error = errno;
    std::error_code ignored;
    std::filesystem::remove(file, ignored);
    fail(file, "closing", error);
  }
}

void sync_folder(const std::filesystem::path& folder) {
  const std::filesystem::path dir = folder.empty() ? "." : folder;
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail(dir, "opening the folder for fsync", errno);
  const int status = ::fsync(fd), error = errno;
  ::close(fd);
  if (status != 0 && error != EINVAL) fail(dir, "fsync of the folder", error);  // EINVAL: not supported there
}

void rename_checked(const std::filesystem::path& from, const std::filesystem::path& to, bool sync) {
  if (::rename(from.c_str(), to.c_str()) != 0) fail(to, fmt::format("renaming {} to it", from.string()).c_str(), errno);
  if (sync) sync_folder(to.parent_path());
}

void replace_file(const std::filesystem::path& file, std::string_view bytes, bool sync) {
  replace_file(file, std::span<const std::string_view>(&bytes, 1), sync);
}

void replace_file(const std::filesystem::path& file, std::span<const std::string_view> parts, bool sync) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  write_file_checked(tmp, parts, sync);
  rename_checked(tmp, file, sync);
}

}  // namespace shockfield::io
