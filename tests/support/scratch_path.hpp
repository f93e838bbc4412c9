#pragma once
// A path in a folder of the system's temporary folder private to this test process
// (shockfield_test_<pid>/name, the folder created on first use), so that tests running side by side
// (ctest -j, several checkouts) never share a file while messages still name the file as given.
// tests/cli/no_shared_scratch.sh fails on a test that names a fixed temporary path instead.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace shockfield::testing {

inline std::filesystem::path scratch_path(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("shockfield_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  return folder / name;
}

}  // namespace shockfield::testing
