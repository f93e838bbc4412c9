#include "shockfield/core/json.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shockfield {

Json& Json::set(const std::string& key, Json v) {
  if (std::holds_alternative<std::nullptr_t>(value)) value = Object{};
  auto* object = std::get_if<Object>(&value);
  if (!object) throw std::logic_error("Json::set on a value that is not an object");
  for (auto& [k, member] : *object)
    if (k == key) {
      member = std::move(v);
      return *this;
    }
  object->emplace_back(key, std::move(v));
  return *this;
}

Json& Json::push(Json v) {
  if (std::holds_alternative<std::nullptr_t>(value)) value = Array{};
  auto* array = std::get_if<Array>(&value);
  if (!array) throw std::logic_error("Json::push on a value that is not an array");
  array->push_back(std::move(v));
  return *this;
}

const Json* Json::find(const std::string& key) const {
  if (const auto* object = std::get_if<Object>(&value))
    for (const auto& [k, member] : *object)
      if (k == key) return &member;
  return nullptr;
}

namespace {

// RFC 8259 §7: quotation mark, reverse solidus and the control characters U+0000–U+001F must be
// escaped; everything else (UTF-8 included) is written as it is.
void write_string(std::string& out, const std::string& s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<int>(c));
        else out += c;
    }
  }
  out += '"';
}

void write_double(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  const std::string text(buffer, end);
  out += text;
  if (text.find_first_of(".e") == std::string::npos) out += ".0";
}

void write(std::string& out, const Json& json, int indent, int depth);

// "[...]" or "{...}": one item per line `indent` deeper (all on one line when indent is 0).
template <class Items, class WriteItem>
void write_container(std::string& out, const Items& items, const char* brackets, int indent, int depth,
                     WriteItem&& write_item) {
  const auto newline = [&](int level) {
    if (indent > 0) out += '\n' + std::string(static_cast<std::size_t>(indent * level), ' ');
  };
  out += brackets[0];
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += indent > 0 ? "," : ", ";
    newline(depth + 1);
    write_item(items[i]);
  }
  if (!items.empty()) newline(depth);
  out += brackets[1];
}

void write(std::string& out, const Json& json, int indent, int depth) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::nullptr_t>) out += "null";
        else if constexpr (std::is_same_v<T, bool>) out += v ? "true" : "false";
        else if constexpr (std::is_same_v<T, double>) write_double(out, v);
        else if constexpr (std::is_same_v<T, long long>) out += std::to_string(v);
        else if constexpr (std::is_same_v<T, std::string>) write_string(out, v);
        else if constexpr (std::is_same_v<T, Json::Array>)
          write_container(out, v, "[]", indent, depth, [&](const Json& item) { write(out, item, indent, depth + 1); });
        else
          write_container(out, v, "{}", indent, depth, [&](const auto& member) {
            write_string(out, member.first);
            out += ": ";
            write(out, member.second, indent, depth + 1);
          });
      },
      json.value);
}

}  // namespace

std::string to_json_text(const Json& json, int indent) {
  std::string out;
  write(out, json, indent, 0);
  if (indent > 0) out += '\n';
  return out;
}

}  // namespace shockfield
