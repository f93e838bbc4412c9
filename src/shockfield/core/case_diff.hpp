#pragma once
// What changed between two versions of a case: the one stored beside a checkpoint and the one
// given to `shockfield run --resume`. The run driver refuses a resume whose changes are not all
// in a method's list of safe keys (matched with key_matches), and prints the changes it accepts.
#include <string>
#include <string_view>
#include <vector>

namespace shockfield {

/// One changed value. `key` is dotted, with array-of-table elements by index as Config names
/// them ("stage[1].steps"); `before`/`after` are TOML values ("0.5", "'text'", "[1, 2]") or
/// "(absent)".
struct CaseChange {
  std::string key;
  std::string before;
  std::string after;
};

/// Every leaf value (a number, string, boolean, date or plain array) that differs, sorted by key.
/// An integer and a float of the same value are equal (10 and 10.0); the top-level [derived] and
/// [provenance] tables of a resolved configuration are ignored. A text that is not TOML is an
/// InputError naming which of the two it is (`before_name`: the file the first was read from).
std::vector<CaseChange> diff_cases(std::string_view before_toml, std::string_view after_toml,
                                   std::string_view before_name = "the case stored at the checkpoint");

/// Whether `dotted_key` matches `pattern`, segment by segment: both are split at '.', and an index
/// "[i]" counts as a segment of its own, so "stage[1].steps" matches "stage.*.steps" and
/// "stage[*].steps". In the pattern, '*' matches any run of characters within one segment
/// ("output.*_interval" matches "output.dump_interval" but not "output.a.b_interval").
bool key_matches(std::string_view dotted_key, std::string_view pattern);

}  // namespace shockfield
