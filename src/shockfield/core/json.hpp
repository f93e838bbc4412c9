#pragma once
// A small JSON value and its writer (RFC 8259), for the machine-readable summary.json of a run
// folder. Objects keep their keys in insertion order so the files read in a stable, logical order.
#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace shockfield {

struct Json {
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;
  std::variant<std::nullptr_t, bool, double, long long, std::string, Array, Object> value;

  Json() : value(nullptr) {}
  Json(std::nullptr_t) : value(nullptr) {}
  Json(bool b) : value(b) {}
  template <std::floating_point T>
  Json(T v) : value(static_cast<double>(v)) {}
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  Json(T v) : value(static_cast<long long>(v)) {}
  Json(const char* s) : value(std::string(s)) {}
  Json(std::string s) : value(std::move(s)) {}
  Json(Array a) : value(std::move(a)) {}
  Json(Object o) : value(std::move(o)) {}

  static Json array() { return Json(Array{}); }
  static Json object() { return Json(Object{}); }

  /// Object member: replaces the value of an existing key (keeping its place) or appends it.
  /// Turns a null into an empty object first. Returns *this, so calls chain.
  Json& set(const std::string& key, Json v);
  /// Array element, appended. Turns a null into an empty array first.
  Json& push(Json v);
  /// The member `key` of an object, or nullptr (also when this is not an object).
  const Json* find(const std::string& key) const;
};

/// The text of `json`: `indent` spaces per level with one member or element per line, or a single
/// line when indent is 0. Non-finite doubles (NaN, ±inf) are written as null; doubles otherwise in
/// the shortest form that reads back to the same double, with ".0" when they look like integers.
std::string to_json_text(const Json& json, int indent = 2);

}  // namespace shockfield
