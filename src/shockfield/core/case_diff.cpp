#include "shockfield/core/case_diff.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/toml_text.hpp"

namespace shockfield {
namespace {

using Leaves = std::map<std::string, const toml::node*>;

void collect_leaves(const toml::table& table, const std::string& prefix, Leaves& out) {
  for (const auto& [k, v] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      collect_leaves(*sub, key, out);
    } else if (const auto* array = v.as_array(); array && !array->empty() && array->is_array_of_tables()) {
      for (std::size_t i = 0; i < array->size(); ++i)
        collect_leaves(*(*array)[i].as_table(), fmt::format("{}[{}]", key, i), out);
    } else {
      out.emplace(key, &v);
    }
  }
}

toml::table parse_case(std::string_view text, const char* which) {
  try {
    toml::table table = toml::parse(text, std::string_view(which));
    table.erase("derived");
    table.erase("provenance");
    return table;
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", which, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

std::string toml_text(const toml::node* node) { return node ? shockfield::toml_text(*node) : "(absent)"; }

// Equal TOML text (the writer's canonical form), or an integer and a float of the same value.
bool same_value(const toml::node& a, const toml::node& b) {
  if (a.is_number() && b.is_number() && a.type() != b.type())
    return a.value<double>() == b.value<double>();
  return toml_text(&a) == toml_text(&b);
}

// Splits "stage[1].steps" into {"stage", "1", "steps"}.
std::vector<std::string_view> segments(std::string_view key) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= key.size(); ++i) {
    if (i == key.size() || key[i] == '.' || key[i] == '[' || key[i] == ']') {
      if (i > start) out.push_back(key.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

// Glob match within one segment: '*' matches any run of characters (iterative, with backtracking
// to the last star).
bool segment_matches(std::string_view text, std::string_view pattern) {
  std::size_t t = 0, p = 0, star = std::string_view::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (p < pattern.size() && pattern[p] == text[t]) {
      ++p;
      ++t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

std::vector<CaseChange> diff_cases(std::string_view before_toml, std::string_view after_toml,
                                   std::string_view before_name) {
  const toml::table before = parse_case(before_toml, std::string(before_name).c_str());
  const toml::table after = parse_case(after_toml, "the case given to --resume");
  Leaves a, b;
  collect_leaves(before, "", a);
  collect_leaves(after, "", b);
  std::vector<CaseChange> changes;
  for (const auto& [key, node] : a) {
    const auto it = b.find(key);
    if (it == b.end() || !same_value(*node, *it->second))
      changes.push_back({key, toml_text(node), toml_text(it == b.end() ? nullptr : it->second)});
  }
  for (const auto& [key, node] : b)
    if (!a.count(key)) changes.push_back({key, "(absent)", toml_text(node)});
  std::sort(changes.begin(), changes.end(),
            [](const CaseChange& x, const CaseChange& y) { return x.key < y.key; });
  return changes;
}

bool key_matches(std::string_view dotted_key, std::string_view pattern) {
  const auto key = segments(dotted_key), pat = segments(pattern);
  if (key.size() != pat.size()) return false;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (!segment_matches(key[i], pat[i])) return false;
  return true;
}

}  // namespace shockfield
