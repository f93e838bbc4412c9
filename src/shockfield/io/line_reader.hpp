#pragma once
// Line-by-line reading of text input files (LAMMPS data and dump files) with errors that name
// the file and the line: every parse failure is an InputError "file:line: what was expected".
#include <filesystem>
#include <fstream>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shockfield::io {

class LineReader {
 public:
  /// Opens `file`; throws InputError when it cannot be read.
  explicit LineReader(const std::filesystem::path& file);
  /// Reads from a stream; `name` stands in for the file name in messages.
  LineReader(std::istream& in, std::string name);

  /// Advances to the next line; false at the end of the input.
  bool next();
  /// Advances to the next line or fails with "unexpected end of file, expected <what>".
  void require_next(const std::string& what);
  const std::string& line() const { return line_; }
  int line_number() const { return line_number_; }
  const std::string& name() const { return name_; }
  /// Whitespace-separated words of the current line.
  std::vector<std::string_view> words() const;

  /// InputError "name:line: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// A whole-word number of the current line; `what` names the expectation in the error.
  double to_double(std::string_view word, const std::string& what) const;
  long long to_int(std::string_view word, const std::string& what) const;

 private:
  std::unique_ptr<std::ifstream> owned_;
  std::istream* in_ = nullptr;
  std::string name_;
  std::string line_;
  int line_number_ = 0;
};

/// Whitespace-separated words of `text`.
std::vector<std::string_view> split_words(std::string_view text);

}  // namespace shockfield::io
