#include "shockfield/app/option_values.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "shockfield/core/error.hpp"

namespace shockfield::app {

std::vector<std::string> split_fields(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

double finite_number(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || text.find_first_not_of(' ', used) != std::string::npos || !std::isfinite(v))
    throw InputError(fmt::format("{}: '{}' is not a finite number", what, text));
  return v;
}

}  // namespace shockfield::app
