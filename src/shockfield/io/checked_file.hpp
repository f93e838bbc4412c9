#pragma once
// Checked output: every open, write, flush, fsync, close and rename is tested, and a failure
// (a full disk, a read-only folder) throws RunError naming the file and the system's reason, so
// a run never ends with exit 0 and a truncated file. Every writer of the run outputs goes
// through CheckedOutput (streams) or replace_file (whole files written at once).
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <string_view>

namespace shockfield::io {

/// A text output stream whose failures throw RunError("<file>: ...") at flush() and close().
/// Writers that take a std::ostream write to stream(); the owner calls flush() after each
/// record it wants kept on a stop, and close() at the end (the destructor closes silently,
/// for the unwinding after another error).
class CheckedOutput {
 public:
  CheckedOutput() = default;
  explicit CheckedOutput(const std::filesystem::path& file, std::ios::openmode mode = std::ios::trunc);
  CheckedOutput(CheckedOutput&&) = default;
  CheckedOutput& operator=(CheckedOutput&&) = default;

  std::ostream& stream() { return out_; }
  template <class T>
  CheckedOutput& operator<<(const T& value) {
    out_ << value;
    note_error();
    return *this;
  }
  void write(std::string_view text);
  /// Pushes the buffered text to the file; throws RunError when any write so far failed.
  void flush();
  /// flush(), then close; throws RunError when closing fails.
  void close();
  bool is_open() const { return out_.is_open(); }
  const std::filesystem::path& file() const { return file_; }

 private:
  /// Keeps errno of the first failed write (a later flush no longer knows it).
  void note_error();
  void check(const char* what);
  std::filesystem::path file_;
  std::ofstream out_;
  int error_ = 0;
};

/// Writes `parts` one after the other to `file` with POSIX calls, each checked (no concatenated
/// copy of large buffers); with `sync`, fsyncs it before closing. On failure the partial file is
/// removed and RunError names it.
void write_file_checked(const std::filesystem::path& file, std::span<const std::string_view> parts, bool sync);
/// fsync of a folder, so a rename into it survives a crash of the machine.
void sync_folder(const std::filesystem::path& folder);
/// Renames `from` over `to` (atomic on POSIX), checked; with `sync`, fsyncs the folder after.
void rename_checked(const std::filesystem::path& from, const std::filesystem::path& to, bool sync);
/// Replaces `file` by `bytes` through `file`.tmp and a rename: readers see the old or the new
/// contents, never half of them. With `sync`, the data and the folder are fsynced.
void replace_file(const std::filesystem::path& file, std::string_view bytes, bool sync = false);
/// The same with the contents given as consecutive parts.
void replace_file(const std::filesystem::path& file, std::span<const std::string_view> parts, bool sync = false);

}  // namespace shockfield::io
