#include "shockfield/io/line_reader.hpp"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::io {

LineReader::LineReader(const std::filesystem::path& file)
    : owned_(std::make_unique<std::ifstream>(file)), in_(owned_.get()), name_(file.string()) {
  if (!*owned_) throw InputError(fmt::format("{}: cannot open file for reading", name_));
}

LineReader::LineReader(std::istream& in, std::string name) : in_(&in), name_(std::move(name)) {}

bool LineReader::next() {
  if (!std::getline(*in_, line_)) return false;
  if (!line_.empty() && line_.back() == '\r') line_.pop_back();  // files written on Windows
  ++line_number_;
  return true;
}

void LineReader::require_next(const std::string& what) {
  if (next()) return;
  throw InputError(fmt::format("{}:{}: unexpected end of file, expected {}", name_,
                               line_number_ + 1, what));
}

std::vector<std::string_view> LineReader::words() const { return split_words(line_); }

void LineReader::fail(const std::string& message) const {
  throw InputError(fmt::format("{}:{}: {}", name_, line_number_, message));
}

double LineReader::to_double(std::string_view word, const std::string& what) const {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(v))
    fail(fmt::format("expected {} (a finite number), got '{}'", what, word));
  return v;
}

long long LineReader::to_int(std::string_view word, const std::string& what) const {
  long long v = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
  if (ec != std::errc() || end != word.data() + word.size())
    fail(fmt::format("expected {} (an integer), got '{}'", what, word));
  return v;
}

std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

}  // namespace shockfield::io
