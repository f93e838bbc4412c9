#include "shockfield/app/python_helpers.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "shockfield/core/error.hpp"

// Set by cmake/install.cmake; the fallbacks keep the file compilable on its own.
#ifndef SHOCKFIELD_BIN_TO_PYTHON
#define SHOCKFIELD_BIN_TO_PYTHON "../lib/python3/dist-packages"
#endif

namespace shockfield::app {
namespace fs = std::filesystem;

std::string shell_quote(const std::string& text) {
  std::string q = "'";
  for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

fs::path python_package_dir() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed = (exe.parent_path() / SHOCKFIELD_BIN_TO_PYTHON).lexically_normal();
    if (fs::is_directory(installed / "shockfield_plot")) return installed;
  }
#ifdef SHOCKFIELD_PYTHON_BUILD_DIR
  const fs::path build = SHOCKFIELD_PYTHON_BUILD_DIR;
  if (fs::is_directory(build / "shockfield_plot")) return build;
#endif
  throw InputError(fmt::format(
      "the Python helpers (shockfield_plot) are neither installed beside this command ({}) nor in "
      "its build tree; reinstall shockfield (cmake --install)",
      (exe.parent_path() / SHOCKFIELD_BIN_TO_PYTHON).lexically_normal().string()));
}

namespace {
bool has_numpy_and_matplotlib(const std::string& interpreter) {
  const std::string probe = interpreter + " -c 'import numpy, matplotlib' >/dev/null 2>&1";
  return std::system(probe.c_str()) == 0;
}
}  // namespace

std::string python_interpreter() {
  if (const char* chosen = std::getenv("SHOCKFIELD_PYTHON"); chosen != nullptr && *chosen != '\0') {
    if (!has_numpy_and_matplotlib(shell_quote(chosen)))
      throw InputError(fmt::format("SHOCKFIELD_PYTHON={} cannot import numpy and matplotlib", chosen));
    return shell_quote(chosen);
  }
  for (const char* candidate : {"python3", "/usr/bin/python3"})
    if (has_numpy_and_matplotlib(candidate)) return candidate;
  throw InputError(
      "no Python 3 with numpy and matplotlib: neither python3 on PATH nor /usr/bin/python3 imports "
      "them; set SHOCKFIELD_PYTHON to an interpreter that does (Debian: apt install python3-numpy "
      "python3-matplotlib)");
}

std::string python_command(const std::string& arguments) {
  const char* old_path = std::getenv("PYTHONPATH");
  std::string path = python_package_dir().string();
  if (old_path != nullptr && *old_path != '\0') path += std::string(":") + old_path;
  return fmt::format("PYTHONPATH={} {} {}", shell_quote(path), python_interpreter(), arguments);
}

bool plot_csv(const std::string& kind, const fs::path& csv, const fs::path& png) {
  std::string cmd;
  try {
    cmd = python_command(fmt::format("-m shockfield_plot {} {} {}", kind, shell_quote(csv.string()), shell_quote(png.string())));
  } catch (const InputError& e) {
    std::fprintf(stderr, "warning: no plot (%s); the CSV is written\n", e.what());
    return false;
  }
  if (std::system(cmd.c_str()) != 0) {
    std::fprintf(stderr, "warning: no plot (%s failed); the CSV is written\n", cmd.c_str());
    return false;
  }
  return true;
}

}  // namespace shockfield::app
