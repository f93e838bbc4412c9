#pragma once
// A path in the system's temporary folder private to this test process (name + process id), so
// that copies of the suite running side by side (several checkouts, ctest -j) never share files.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace shockfield::testing {

inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
}

}  // namespace shockfield::testing
