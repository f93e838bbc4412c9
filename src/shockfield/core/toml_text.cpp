#include "shockfield/core/toml_text.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <sstream>

namespace shockfield {
namespace {

bool number_char(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

// The shortest text of a float literal `token`, or the token itself when it is none.
std::string shortest(std::string_view token) {
  if (token.find_first_of(".eE") == std::string_view::npos) return std::string(token);  // an integer
  const std::string_view digits = token.front() == '+' ? token.substr(1) : token;
  double v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::string(token);
  char buffer[32];
  std::string out(buffer, static_cast<std::size_t>(std::to_chars(buffer, buffer + sizeof buffer, v).ptr - buffer));
  if (out.find_first_of(".e") == std::string::npos) out += ".0";  // stays a TOML float
  return out;
}

}  // namespace

std::string shortest_floats(std::string_view toml) {
  std::string out;
  out.reserve(toml.size());
  char quote = 0;          // the open string's quote, 0 outside strings
  char previous = 0;       // the last character outside strings that is not a blank or a line end
  for (std::size_t i = 0; i < toml.size();) {
    const char c = toml[i];
    if (quote) {  // inside a string: copied as it is ("..." has backslash escapes, '...' none)
      out += c;
      if (c == '\\' && quote == '"' && i + 1 < toml.size()) out += toml[++i];
      else if (c == quote) quote = 0;
      ++i;
      continue;
    }
    if (c == '#') {  // a comment: copied to the end of its line
      const std::size_t end = std::min(toml.find('\n', i), toml.size());
      out.append(toml.substr(i, end - i));
      i = end;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    // A value starts after '=' (a key = value), '[' or ',' inside an array; a header line's '['
    // is followed by a key, which does not start like a number.
    const bool value_start = previous == '=' || previous == '[' || previous == ',';
    if (value_start && (number_char(c) && c != '.' && c != 'e' && c != 'E')) {
      std::size_t j = i;
      while (j < toml.size() && number_char(toml[j])) ++j;
      out += shortest(toml.substr(i, j - i));
      previous = toml[j - 1];
      i = j;
      continue;
    }
    out += c;
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') previous = c;  // arrays may span lines
    ++i;
  }
  return out;
}

std::string toml_text(const toml::node& node) {
  std::ostringstream out;
  node.visit([&](const auto& v) { out << v; });
  return shortest_floats(out.str());
}

}  // namespace shockfield
