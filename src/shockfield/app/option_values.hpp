#pragma once
// Values inside command-line option strings ("x,y,z:ax,ay,az:r", "z:5", "1,2,3"), parsed strictly:
// the whole field must be the value, or InputError names the option and the field.
#include <string>
#include <vector>

namespace shockfield::app {

/// Splits on `sep`, keeping empty fields (so that "1,,2" is an error, not "1,2").
std::vector<std::string> split_fields(const std::string& text, char sep);
/// A finite number filling the whole of `text` (spaces after it allowed).
double finite_number(const std::string& text, const std::string& what);

}  // namespace shockfield::app
