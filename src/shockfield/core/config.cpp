#include "shockfield/core/config.hpp"

#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/toml_text.hpp"

namespace shockfield {

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;  // NaN and +-inf: every range holds finite numbers only
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

bool Range::contains(long long v) const {
  // Compared in long double, whose 64-bit mantissa holds every long long exactly: a double
  // would round 2^63 - 1 up to 2^63 and let it pass a bound of 9.2e18.
  const long double x = static_cast<long double>(v);
  if (lo_open ? !(x > lo) : !(x >= lo)) return false;
  if (hi_open ? !(x < hi) : !(x <= hi)) return false;
  return true;
}

std::string Range::describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return fmt::format("in {}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  if (has_lo) return fmt::format("{} {}", lo_open ? ">" : ">=", lo);
  if (has_hi) return fmt::format("{} {}", hi_open ? "<" : "<=", hi);
  return "a finite number";
}

Config Config::load(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw InputError(fmt::format("{}: file not found", file.string()));
  try {
    auto shared = std::make_shared<Shared>();
    shared->file = file.string();
    shared->root = toml::parse_file(file.string());
    return Config(shared, &shared->root, "");
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", file.string(),
                                 e.source().begin.line, e.source().begin.column, e.description()));
  }
}

Config Config::parse(std::string_view text, const std::string& name) {
  try {
    auto shared = std::make_shared<Shared>();
    shared->file = name;
    shared->root = toml::parse(text, name);
    return Config(shared, &shared->root, "");
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", name, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

std::string Config::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const toml::node* Config::node(std::string_view key) const { return table_->get(key); }

bool Config::has(std::string_view key) const { return node(key) != nullptr; }

void Config::mark(std::string_view key) const { shared_->read_keys.insert(key_path(key)); }

void Config::fail(std::string_view key, const std::string& expectation) const {
  const toml::node* n = key.empty() ? nullptr : node(key);
  std::string where = shared_->file;
  if (const std::string* set = override_for(key_path(key))) where += fmt::format(" (from --set {})", *set);
  else if (n && n->source().begin.line > 0) where += fmt::format(":{}", n->source().begin.line);
  throw InputError(fmt::format("{}: key '{}': {}", where, key_path(key), expectation));
}

namespace {
// Inserts `value` at the dotted path `path` of `root`, creating tables on the way. Paths with
// array indices (name[3]) address the elements of arrays of tables.
toml::table& table_at(toml::table& root, const std::string& path) {
  toml::table* t = &root;
  std::stringstream ss(path);
  std::string part;
  while (std::getline(ss, part, '.')) {
    if (part.empty()) continue;
    const auto bracket = part.find('[');
    if (bracket == std::string::npos) {
      if (!t->contains(part)) t->insert(part, toml::table{});
      t = t->get(part)->as_table();
    } else {
      const std::string name = part.substr(0, bracket);
      const auto index = static_cast<std::size_t>(std::stoul(part.substr(bracket + 1)));
      if (!t->contains(name)) t->insert(name, toml::array{});
      toml::array* a = t->get(name)->as_array();
      while (a->size() <= index) a->push_back(toml::table{});
      t = (*a)[index].as_table();
    }
  }
  return *t;
}
}  // namespace

template <class T>
void Config::record(std::string_view key, const T& value) const {
  table_at(shared_->resolved, path_).insert_or_assign(std::string(key), value);
}
template void Config::record<std::string>(std::string_view, const std::string&) const;  // config_case.cpp

double Config::number(std::string_view key, const toml::node& n, Range range) const {
  double v = 0;
  if (auto f = n.as_floating_point()) v = f->get();
  else if (auto i = n.as_integer()) v = static_cast<double>(i->get());
  else fail(key, fmt::format("expected a number {}, got a {}", range.describe(), toml::impl::node_type_friendly_names[static_cast<int>(n.type())]));
  if (!std::isfinite(v) || !range.contains(v))
    fail(key, fmt::format("expected a number {}, got {}", range.describe(), v));
  return v;
}

double Config::get_double(std::string_view key, Range range) const {
  const toml::node* n = node(key);
  if (!n) fail(key, fmt::format("missing required value (a number {})", range.describe()));
  mark(key);
  const double v = number(key, *n, range);
  record(key, v);
  return v;
}

long long Config::get_int(std::string_view key, Range range) const {
  const toml::node* n = node(key);
  if (!n) fail(key, fmt::format("missing required value (an integer {})", range.describe()));
  mark(key);
  auto i = n->as_integer();
  if (!i) fail(key, fmt::format("expected an integer {}", range.describe()));
  if (!range.contains(static_cast<long long>(i->get())))
    fail(key, fmt::format("expected an integer {}, got {}", range.describe(), i->get()));
  record(key, i->get());
  return i->get();
}

bool Config::get_bool(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) fail(key, "missing required value (true or false)");
  mark(key);
  auto b = n->as_boolean();
  if (!b) fail(key, "expected true or false");
  record(key, b->get());
  return b->get();
}

std::string Config::get_string(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) fail(key, "missing required value (a string)");
  mark(key);
  auto s = n->as_string();
  if (!s) fail(key, "expected a string in quotes");
  record(key, s->get());
  return s->get();
}

namespace {
std::string join_quoted(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", \"" : "\"") + items[i] + "\"";
  return out;
}
}  // namespace

std::string Config::get_choice(std::string_view key, const std::vector<std::string>& choices) const {
  const std::string v = get_string(key);
  for (const auto& c : choices)
    if (c == v) return v;
  fail(key, fmt::format("expected one of {}, got \"{}\"", join_quoted(choices), v));
}

std::vector<double> Config::get_doubles(std::string_view key, std::size_t count, Range range) const {
  const toml::node* n = node(key);
  const std::string what = count ? fmt::format("an array of {} numbers", count) : "an array of numbers";
  if (!n) fail(key, "missing required value (" + what + ")");
  mark(key);
  auto a = n->as_array();
  if (!a || (count && a->size() != count)) fail(key, "expected " + what);
  std::vector<double> out;
  toml::array rec;
  for (const auto& e : *a) {
    out.push_back(number(key, e, range));
    rec.push_back(out.back());
  }
  record(key, rec);
  return out;
}

std::vector<long long> Config::get_ints(std::string_view key, std::size_t count, Range range) const {
  const toml::node* n = node(key);
  const std::string what = count ? fmt::format("an array of {} integers", count) : "an array of integers";
  if (!n) fail(key, "missing required value (" + what + ")");
  mark(key);
  auto a = n->as_array();
  if (!a || (count && a->size() != count)) fail(key, "expected " + what);
  std::vector<long long> out;
  toml::array rec;
  for (const auto& e : *a) {
    auto i = e.as_integer();
    if (!i || !range.contains(static_cast<long long>(i->get())))
      fail(key, fmt::format("expected {} {}", what, range.describe()));
    out.push_back(i->get());
    rec.push_back(i->get());
  }
  record(key, rec);
  return out;
}

std::vector<std::string> Config::get_strings(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) fail(key, "missing required value (an array of strings)");
  mark(key);
  auto a = n->as_array();
  if (!a) fail(key, "expected an array of strings");
  std::vector<std::string> out;
  toml::array rec;
  for (const auto& e : *a) {
    auto s = e.as_string();
    if (!s) fail(key, "expected an array of strings");
    out.push_back(s->get());
    rec.push_back(s->get());
  }
  record(key, rec);
  return out;
}

double Config::get_double_or(std::string_view key, double fallback, Range range) const {
  if (has(key)) return get_double(key, range);
  // An infinite default (an open region bound) is not recorded: case files refuse non-finite
  // numbers, and leaving the key out replays as the same default.
  if (std::isfinite(fallback)) record(key, fallback);
  return fallback;
}
long long Config::get_int_or(std::string_view key, long long fallback, Range range) const {
  if (has(key)) return get_int(key, range);
  record(key, fallback);
  return fallback;
}
bool Config::get_bool_or(std::string_view key, bool fallback) const {
  if (has(key)) return get_bool(key);
  record(key, fallback);
  return fallback;
}
std::string Config::get_string_or(std::string_view key, const std::string& fallback) const {
  if (has(key)) return get_string(key);
  record(key, fallback);
  return fallback;
}
std::string Config::get_choice_or(std::string_view key, const std::vector<std::string>& choices,
                                  const std::string& fallback) const {
  if (has(key)) return get_choice(key, choices);
  record(key, fallback);
  return fallback;
}
std::vector<double> Config::get_doubles_or(std::string_view key, const std::vector<double>& fallback,
                                           Range range) const {
  if (has(key)) return get_doubles(key, fallback.size(), range);
  toml::array rec;
  for (double v : fallback) rec.push_back(v);
  record(key, rec);
  return fallback;
}

Config Config::table(std::string_view key) const {
  auto t = optional_table(key);
  if (!t) fail(key, "missing required table [" + key_path(key) + "]");
  return *t;
}

std::optional<Config> Config::optional_table(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  mark(key);
  auto t = n->as_table();
  if (!t) fail(key, "expected a table [" + key_path(key) + "]");
  table_at(shared_->resolved, key_path(key));
  return Config(shared_, t, key_path(key));
}

Config Config::table_or_empty(std::string_view key) const {
  if (auto t = optional_table(key)) return *t;
  static const toml::table empty;
  table_at(shared_->resolved, key_path(key));
  return Config(shared_, &empty, key_path(key));
}

std::vector<Config> Config::tables(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return {};
  mark(key);
  auto a = n->as_array();
  if (!a || !a->is_array_of_tables()) fail(key, "expected an array of tables [[" + key_path(key) + "]]");
  std::vector<Config> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string p = fmt::format("{}[{}]", key_path(key), i);
    shared_->read_keys.insert(p);
    table_at(shared_->resolved, p);
    out.push_back(Config(shared_, (*a)[i].as_table(), p));
  }
  return out;
}

void Config::derive(const std::string& key, double value) const {
  check_replayed(key, toml::value<double>(value));
  table_at(shared_->resolved, "derived").insert_or_assign(key, value);
}
void Config::derive(const std::string& key, long long value) const {
  check_replayed(key, toml::value<std::int64_t>(value));
  table_at(shared_->resolved, "derived").insert_or_assign(key, value);
}
void Config::derive(const std::string& key, const std::string& value) const {
  check_replayed(key, toml::value<std::string>(value));
  table_at(shared_->resolved, "derived").insert_or_assign(key, value);
}

namespace {
// `origin(key, node)` says where an unknown key came from ("line 3", "from --set a.b=1").
template <class Origin>
void collect_unknown(const toml::table& t, const std::string& prefix,
                     const std::set<std::string>& read, const Origin& origin,
                     std::vector<std::string>& out) {
  for (const auto& [k, v] : t) {
    const std::string full = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (!read.count(full)) {
      out.push_back(fmt::format("'{}' ({})", full, origin(full, v)));
      continue;
    }
    if (auto sub = v.as_table()) collect_unknown(*sub, full, read, origin, out);
    if (auto arr = v.as_array(); arr && arr->is_array_of_tables())
      for (std::size_t i = 0; i < arr->size(); ++i)
        collect_unknown(*(*arr)[i].as_table(), fmt::format("{}[{}]", full, i), read, origin, out);
  }
}
}  // namespace

void Config::check_unknown_keys() const {
  std::vector<std::string> unknown;
  const auto origin = [this](const std::string& key, const toml::node& v) {
    if (const std::string* set = override_for(key, true)) return "from --set " + *set;
    return fmt::format("line {}", v.source().begin.line);
  };
  collect_unknown(shared_->root, "", shared_->read_keys, origin, unknown);
  if (unknown.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < unknown.size(); ++i) list += (i ? ", " : "") + unknown[i];
  throw InputError(fmt::format("{}: unknown key{} {} (check the spelling against the input "
                               "reference in docs/)",
                               shared_->file, unknown.size() > 1 ? "s" : "", list));
}

std::string Config::resolved_toml() const {
  std::ostringstream out;
  out << "# Resolved configuration: every value the run used, defaults included, the derived\n"
         "# values under [derived] and where the run came from under [provenance]. It can be run\n"
         "# again as a case file: its [derived] values are then checked against a fresh derivation.\n";
  for (const auto& [key, text] : shared_->overrides) out << "# --set " << text << "\n";
  toml::table resolved = shared_->resolved;
  if (shared_->provenance) resolved.insert_or_assign("provenance", *shared_->provenance);
  out << resolved << "\n";
  return shortest_floats(out.str());
}

}  // namespace shockfield
