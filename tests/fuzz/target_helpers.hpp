#pragma once
// What the fuzz targets (targets.cpp, file_targets.cpp) share: file helpers, a case run through
// the shockfield binary, and a run folder stopped after a few steps (the base of the checkpoint
// and resume targets).
#include <filesystem>
#include <string>
#include <vector>

#include "targets.hpp"

namespace shockfield::fuzz {

std::string read_text(const std::filesystem::path& file);
void write_text(const std::filesystem::path& file, const std::string& text);
std::string replace_all(std::string s, const std::string& from, const std::string& to);

/// `shockfield run CASE --output WORK/out -q -j 1 EXTRA...` in `work`.
Outcome run_case(const Context& c, const std::filesystem::path& case_file, const std::filesystem::path& work,
                 std::vector<std::string> extra);

/// A run folder (BASE/out) of `case_file` stopped after `steps` steps (exit 130, a checkpoint
/// written), made anew in c.work/base_NAME; BASE/case.toml is the case. Throws
/// std::runtime_error when the run wrote no checkpoint.
std::filesystem::path stopped_run(const Context& c, const std::string& name, const std::filesystem::path& case_file,
                                  int steps);

/// The first non-finite number written as a value in a TOML or CSV text ("= nan", ",-inf"), with
/// its line, or "" when there is none.
std::string non_finite_value(const std::string& text);

}  // namespace shockfield::fuzz
