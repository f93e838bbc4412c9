#pragma once
// TOML text as shockfield writes it (config.resolved.toml, checkpoint.case.toml, the values in
// messages): toml++'s writer with every float in the shortest form that reads back to the same
// double. Debian's toml++ 3.3 library is built without floating-point std::to_chars and prints
// 17 significant digits (0.33 as 0.33000000000000002); docs/conventions.md.
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace shockfield {

/// A TOML text printed by toml++ with each float literal outside strings, keys and headers
/// rewritten by std::to_chars (shortest round trip), ".0" kept where that form is an integer.
std::string shortest_floats(std::string_view toml);

/// One value as TOML text (shortest floats).
std::string toml_text(const toml::node& node);

}  // namespace shockfield
