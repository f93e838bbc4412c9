// The parts of Config a run adds to plain case reading: `--set` overrides, a resolved
// configuration fed back as a case (its [derived] checked against a fresh derivation), the input
// files a case names (for provenance), and the case text kept for the resume check.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/toml_text.hpp"

namespace shockfield {
namespace {

constexpr const char* kSetUsage =
    "expected KEY=VALUE: a dotted key as in the case file (md.timestep, stage[1].steps), then a "
    "value in TOML syntax (1.5, 10, true, \"text\", [1, 2])";

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

// One segment of a dotted --set key: a bare TOML key, optionally with an array-of-tables index.
struct KeySegment {
  std::string name;
  std::optional<std::size_t> index;
};

std::optional<std::vector<KeySegment>> split_key(const std::string& key) {
  std::vector<KeySegment> out;
  std::stringstream ss(key);
  std::string part;
  while (std::getline(ss, part, '.')) {
    KeySegment seg;
    const auto bracket = part.find('[');
    seg.name = part.substr(0, bracket);
    if (bracket != std::string::npos) {
      const std::string digits = part.substr(bracket + 1, part.size() - bracket - 2);
      if (part.back() != ']' || digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
      seg.index = std::stoul(digits);
    }
    if (seg.name.empty() ||
        seg.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
            std::string::npos)
      return std::nullopt;
    out.push_back(std::move(seg));
  }
  if (out.empty() || key.back() == '.') return std::nullopt;
  return out;
}

// True when `inner` names a value inside the table `outer` ("a.b.c" or "a.b[2]" inside "a.b").
bool is_within(const std::string& inner, const std::string& outer) {
  return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
         (inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

// A replayed derived value equals a fresh one: doubles to 1e-12 relative (NaN equal to NaN),
// integers and strings exactly.
bool same_derived(const toml::node& stored, const toml::node& fresh) {
  if (fresh.is_floating_point()) {
    if (!stored.is_number()) return false;
    const double a = *stored.value<double>(), b = *fresh.value<double>();
    if (a == b || (std::isnan(a) && std::isnan(b))) return true;
    return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b));
  }
  if (fresh.is_integer()) return stored.is_integer() && *stored.value<long long>() == *fresh.value<long long>();
  return stored.is_string() && stored.value<std::string>() == fresh.value<std::string>();
}

}  // namespace

Config Config::load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  Config config = load(file);
  toml::table& root = config.shared_->root;
  if (auto* derived = root.get_as<toml::table>("derived")) {
    config.shared_->replayed_derived = std::move(*derived);
    root.erase("derived");
  } else if (root.contains("derived")) {
    config.fail("derived", "expected the table [derived] of a resolved configuration");
  }
  root.erase("provenance");
  for (const auto& text : overrides) config.apply_override(text);
  return config;
}

void Config::apply_override(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw InputError(fmt::format("--set '{}': {}", text, kSetUsage));
  const std::string key = trim(std::string_view(text).substr(0, eq));
  const std::string value = trim(std::string_view(text).substr(eq + 1));
  const auto segments = split_key(key);
  if (!segments || segments->back().index) throw InputError(fmt::format("--set '{}': {}", text, kSetUsage));
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + value, std::string_view("--set"));
    if (parsed.size() != 1) throw InputError(fmt::format("--set '{}': the value is more than one TOML value", text));
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("--set '{}': the value is not TOML ({}); text needs quotes, as in "
                                 "--set 'name=\"text\"'", text, e.description()));
  }
  toml::table* table = &shared_->root;
  std::string path;
  for (std::size_t i = 0; i + 1 < segments->size(); ++i) {
    const KeySegment& seg = (*segments)[i];
    path += (path.empty() ? "" : ".") + seg.name;
    if (!seg.index) {
      if (!table->contains(seg.name)) table->insert(seg.name, toml::table{});
      table = table->get_as<toml::table>(seg.name);
      if (!table)
        throw InputError(fmt::format("--set '{}': '{}' in {} is not a table (an element of an array of "
                                     "tables is written as {}[0])", text, path, file(), path));
      continue;
    }
    auto* array = table->get_as<toml::array>(seg.name);
    if (!array || !array->is_array_of_tables() || *seg.index >= array->size())
      throw InputError(fmt::format("--set '{}': {} has no [[{}]] table number {} (they count from 0)",
                                   text, file(), path, *seg.index));
    table = (*array)[*seg.index].as_table();
    path += fmt::format("[{}]", *seg.index);
  }
  const std::string last = segments->back().name;
  parsed["value"].node()->visit([&](const auto& v) { table->insert_or_assign(last, v); });
  shared_->overrides[path.empty() ? last : path + "." + last] = text;
}

const std::string* Config::override_for(const std::string& dotted_key, bool descendants) const {
  for (const auto& [key, text] : shared_->overrides)
    if (key == dotted_key || is_within(dotted_key, key) || (descendants && is_within(key, dotted_key)))
      return &text;
  return nullptr;
}

void Config::check_replayed(const std::string& key, const toml::node& fresh) const {
  shared_->derived_keys.insert(key);
  if (!shared_->replayed_derived) return;
  const toml::node* stored = shared_->replayed_derived->get(key);
  if (!stored || same_derived(*stored, fresh)) return;
  const int line = static_cast<int>(stored->source().begin.line);
  throw InputError(fmt::format(
      "{}{}: [derived] {} = {} in the file, but this case derives {} = {}: the case's values are "
      "not the ones it was resolved with (remove [derived] from the file to run it as it is now)",
      file(), line > 0 ? fmt::format(":{}", line) : "", key, toml_text(*stored), key, toml_text(fresh)));
}

void Config::check_replayed_derived() const {
  if (!shared_->replayed_derived) return;
  std::vector<std::string> never;
  for (const auto& [key, value] : *shared_->replayed_derived)
    if (!shared_->derived_keys.count(std::string(key.str()))) never.push_back(std::string(key.str()));
  if (never.empty()) return;
  throw InputError(fmt::format(
      "{}: [derived] has {} that this case does not derive: {} (the file was resolved from another "
      "case or with other options; remove [derived] from the file to run it as it is now)",
      file(), never.size() == 1 ? "a key" : "keys", fmt::join(never, ", ")));
}

std::filesystem::path Config::get_input_file(std::string_view key) const {
  return get_input_file(key, {std::filesystem::path(file()).parent_path()});
}

std::filesystem::path Config::get_input_file(std::string_view key,
                                             const std::vector<std::filesystem::path>& folders) const {
  const std::string given = get_string(key);
  std::vector<std::filesystem::path> tried;
  if (std::filesystem::path(given).is_absolute()) tried.push_back(given);
  else
    for (const auto& folder : folders) tried.push_back(folder / given);
  std::vector<std::string> failures;
  for (auto& path : tried) {
    path = std::filesystem::absolute(path).lexically_normal();
    if (std::filesystem::is_regular_file(path)) {
      record(key, path.string());
      auto& files = shared_->input_files;
      if (std::find(files.begin(), files.end(), path) == files.end()) files.push_back(path);
      return path;
    }
    failures.push_back(fmt::format("{}: cannot open ({})", path.string(),
                                   std::filesystem::exists(path) ? "not a regular file" : "no such file"));
  }
  fail(key, fmt::format("file '{}' not found; tried {}", given, fmt::join(failures, ", ")));
}

const std::vector<std::filesystem::path>& Config::input_files() const { return shared_->input_files; }

std::string Config::case_toml() const {
  std::ostringstream out;
  out << shared_->root << "\n";
  return out.str();
}

void Config::set_provenance(const toml::table& provenance) const { shared_->provenance = provenance; }

}  // namespace shockfield
