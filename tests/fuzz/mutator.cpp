#include "mutator.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <utility>
#include <vector>

namespace shockfield::fuzz {
namespace {

// Replacement tokens: non-finite and extreme reals, integers at and beyond the int and
// long long limits, negative, zero and empty values.
constexpr std::array<const char*, 22> kExtremes{
    "nan", "NaN", "inf", "-inf", "Infinity", "-0", "-0.0", "1e300", "-1e300", "1e-300",
    "9223372036854775807", "-9223372036854775808", "99999999999999999999", "2147483648",
    "4294967296", "9.2e18", "1e20", "-1", "0", "", "1e308", "2.5e-308"};

// Byte spans of the numbers in a text: digits with signs, points and exponents around them.
std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const auto part = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E';
  };
  std::size_t i = 0;
  while (i < s.size()) {
    if (!part(s[i])) { ++i; continue; }
    const std::size_t start = i;
    bool digit = false;
    while (i < s.size() && part(s[i])) digit |= std::isdigit(static_cast<unsigned char>(s[i++])) != 0;
    const bool inside_word = start > 0 && (std::isalpha(static_cast<unsigned char>(s[start - 1])) || s[start - 1] == '_');
    if (digit && !inside_word) out.emplace_back(start, i - start);
  }
  return out;
}

// Byte offsets of line starts.
std::vector<std::size_t> line_starts(const std::string& s) {
  std::vector<std::size_t> out{0};
  for (std::size_t i = 0; i + 1 < s.size(); ++i)
    if (s[i] == '\n') out.push_back(i + 1);
  return out;
}

std::size_t line_end(const std::string& s, std::size_t start) {
  const auto e = s.find('\n', start);
  return e == std::string::npos ? s.size() : e + 1;
}

}  // namespace

std::uint64_t mutant_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void Mutator::note(const std::string& what) {
  description_ += (description_.empty() ? "" : "; ") + what;
}

std::string Mutator::mutate(const std::string& input) {
  std::string s = input;
  description_.clear();
  const std::size_t count = 1 + below(3);
  for (std::size_t k = 0; k < count && !s.empty(); ++k) {
    if (binary_) {
      switch (below(4)) {
        case 0: flip_byte(s); break;
        case 1: binary_run(s); break;
        case 2: truncate(s); break;
        default: {  // repeat a block in place of another
          const std::size_t n = 1 + below(std::min<std::size_t>(s.size(), 4096));
          const std::size_t from = below(s.size() - n + 1), to = below(s.size() - n + 1);
          s.replace(to, n, s.substr(from, n));
          note(fmt::format("copied {} bytes from {} to {}", n, from, to));
        }
      }
      continue;
    }
    switch (below(10)) {
      case 0: flip_byte(s); break;
      case 1: delete_line(s); break;
      case 2: duplicate_line(s); break;
      case 3: truncate(s); break;
      case 4: swap_numbers(s); break;
      default: replace_number(s);  // half of all mutations: the extremes matter most
    }
  }
  return s;
}

void Mutator::flip_byte(std::string& s) {
  const std::size_t at = below(s.size());
  const auto old = static_cast<unsigned char>(s[at]);
  s[at] = below(2) ? static_cast<char>(old ^ (1u << below(8))) : static_cast<char>(below(256));
  note(fmt::format("byte {} 0x{:02x} -> 0x{:02x}", at, old, static_cast<unsigned char>(s[at])));
}

void Mutator::replace_number(std::string& s) {
  const auto spans = numbers(s);
  if (spans.empty()) return flip_byte(s);
  const std::size_t pick = below(2) ? below(std::min<std::size_t>(spans.size(), 40)) : below(spans.size());
  const auto [at, len] = spans[pick];
  std::string token;
  if (below(5) == 0) {  // the same number scaled by a power of ten, or negated
    token = s.substr(at, len);
    if (below(2)) token.insert(0, 1, '-');
    else token += fmt::format("e{}", below(2) ? 300 : -300);
  } else {
    token = kExtremes[below(kExtremes.size())];
  }
  note(fmt::format("number {} '{}' -> '{}'", pick, s.substr(at, len), token));
  s.replace(at, len, token);
}

void Mutator::swap_numbers(std::string& s) {
  const auto spans = numbers(s);
  if (spans.size() < 2) return flip_byte(s);
  std::size_t a = below(std::min<std::size_t>(spans.size(), 60)), b = below(spans.size());
  if (a == b) return replace_number(s);
  if (a > b) std::swap(a, b);
  const auto [pa, la] = spans[a];
  const auto [pb, lb] = spans[b];
  const std::string ta = s.substr(pa, la), tb = s.substr(pb, lb);
  s.replace(pb, lb, ta);  // the later one first, so that the earlier offset stays valid
  s.replace(pa, la, tb);
  note(fmt::format("numbers {} '{}' and {} '{}' swapped", a, ta, b, tb));
}

void Mutator::delete_line(std::string& s) {
  const auto starts = line_starts(s);
  const std::size_t line = below(std::min<std::size_t>(starts.size(), below(2) ? 30 : starts.size()));
  const std::size_t b = starts[line];
  s.erase(b, line_end(s, b) - b);
  note(fmt::format("line {} deleted", line + 1));
}

void Mutator::duplicate_line(std::string& s) {
  const auto starts = line_starts(s);
  const std::size_t line = below(std::min<std::size_t>(starts.size(), below(2) ? 30 : starts.size()));
  const std::size_t b = starts[line];
  std::string text = s.substr(b, line_end(s, b) - b);
  if (text.empty() || text.back() != '\n') text += '\n';
  s.insert(b, text);
  note(fmt::format("line {} duplicated", line + 1));
}

void Mutator::truncate(std::string& s) {
  const std::size_t at = below(s.size());
  s.resize(at);
  note(fmt::format("truncated at byte {}", at));
}

void Mutator::binary_run(std::string& s) {
  const std::size_t n = 1 + below(std::min<std::size_t>(s.size(), 512));
  const std::size_t at = below(s.size() - n + 1);
  const bool zero = below(2) == 0;
  for (std::size_t i = at; i < at + n; ++i) s[i] = zero ? '\0' : static_cast<char>(below(256));
  note(fmt::format("{} {} bytes at {}", zero ? "zeroed" : "randomised", n, at));
}

}  // namespace shockfield::fuzz
