#include "target_helpers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace shockfield::fuzz {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read a fuzz input", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

Outcome run_case(const Context& c, const fs::path& case_file, const fs::path& work, std::vector<std::string> extra) {
  std::vector<std::string> argv{c.shockfield.string(), "run", case_file.string(), "--output",
                                (work / "out").string(), "-q", "-j", "1"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return run_program(argv, work, c.limits);
}

fs::path stopped_run(const Context& c, const std::string& name, const fs::path& case_file, int steps) {
  const fs::path base = c.work / ("base_" + name);
  fs::remove_all(base);  // made anew by every fuzz run: the binary (and its formats) may have changed
  fs::create_directories(base);
  fs::copy_file(case_file, base / "case.toml");
  const Outcome o = run_case(c, base / "case.toml", base, {"--stop-after", std::to_string(steps)});
  if (!fs::exists(base / "out/checkpoint.h5"))
    throw std::runtime_error(fmt::format("the {} fuzz target's base run wrote no checkpoint ({}): {}", name,
                                         kind_name(o.kind), o.message));
  return base;
}

std::string non_finite_value(const std::string& text) {
  // A value position (after '=', ',', '[' or '{', or at the start of a CSV line), then nan or inf.
  static const std::regex value(R"((^|[=,\[{])[ \t]*[-+]?(nan|inf|NaN|Inf|INF|NAN)\b)", std::regex::ECMAScript | std::regex::multiline);
  std::smatch m;
  if (!std::regex_search(text, m, value)) return "";
  const auto start = text.rfind('\n', static_cast<std::size_t>(m.position(0))) + 1;  // npos + 1 = 0
  const auto line = static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(start), '\n')) + 1;
  return fmt::format("line {}: {}", line, text.substr(start, text.find('\n', start) - start));
}

}  // namespace shockfield::fuzz
