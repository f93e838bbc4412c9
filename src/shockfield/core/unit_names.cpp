#include "shockfield/core/unit_names.hpp"

#include <fmt/format.h>

#include <cctype>
#include <vector>

#include "shockfield/core/error.hpp"

namespace shockfield::units {
namespace {

struct Factor {
  std::string base;
  int power = 1;
};

// "kg" → {kg, 1}, "m3" or "m^3" → {m, 3}.
Factor factor_of(const std::string& text, const std::string& unit) {
  Factor f;
  std::size_t i = 0;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) f.base += text[i++];
  if (i < text.size() && text[i] == '^') ++i;
  const std::string digits = text.substr(i);
  const bool all_digits = !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
  if (f.base.empty() || (!digits.empty() && !all_digits) || digits.size() > 2)
    throw InputError(fmt::format("unit '{}': cannot spell '{}' in a column name; expected units such as Pa, kg/m3, "
                                 "m/s, 1/A^3", unit, text));
  if (all_digits) f.power = std::stoi(digits);
  return f;
}

std::string spelled(const std::vector<Factor>& factors) {
  std::string s;
  for (const Factor& f : factors)
    s += (s.empty() ? "" : "_") + f.base + (f.power == 1 ? "" : std::to_string(f.power));
  return s;
}

}  // namespace

std::string column_suffix(const std::string& unit, int power) {
  if (unit.empty()) return "unknown";
  if (unit == "1") return "1";
  // Numerator factors before the first "/", denominator factors after each "/".
  std::vector<Factor> above, below;
  std::string token;
  bool denominator = false;
  const auto flush = [&] {
    if (!token.empty() && token != "1") (denominator ? below : above).push_back(factor_of(token, unit));
    token.clear();
  };
  for (const char c : unit) {
    if (c == '/') {
      flush();
      denominator = true;
    } else if (c == '*' || c == '.' || c == ' ') {
      flush();
    } else {
      token += c;
    }
  }
  flush();
  for (Factor& f : above) f.power *= power;
  for (Factor& f : below) f.power *= power;
  if (power < 0) std::swap(above, below);
  for (Factor& f : above) f.power = std::abs(f.power);
  for (Factor& f : below) f.power = std::abs(f.power);
  if (above.empty()) return "per_" + spelled(below);
  return below.empty() ? spelled(above) : spelled(above) + "_" + spelled(below);
}

std::string column_name(const std::string& name, const std::string& unit, int power) {
  return name + "_" + column_suffix(unit, power);
}

std::string lammps_length_unit(const std::string& style) {
  if (style == "real" || style == "metal") return "A";
  if (style == "si") return "m";
  if (style == "cgs") return "cm";
  if (style == "electron") return "Bohr";
  if (style == "micro") return "um";
  if (style == "nano") return "nm";
  if (style == "lj") return "1";
  return "";
}

}  // namespace shockfield::units
