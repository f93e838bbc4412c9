#pragma once
// Where the `shockfield` command finds its Python side (docs/install.md): the folder holding the
// Python packages (shockfield, shockfield_plot) and the interpreter that runs them.
#include <filesystem>
#include <string>

namespace shockfield::app {

/// The folder holding shockfield_plot/: BIN/../<python install dir> for an installed command
/// (relative to the executable itself), else, for the build tree's command, the build tree's
/// python/ (the package with its compiled module). Throws InputError when neither exists.
std::filesystem::path python_package_dir();

/// The interpreter for the helpers: $SHOCKFIELD_PYTHON when set; else the first of `python3` on
/// PATH and /usr/bin/python3 that imports numpy and matplotlib. Throws InputError saying to set
/// SHOCKFIELD_PYTHON when none does.
std::string python_interpreter();

/// A shell command running `arguments` with that interpreter and python_package_dir() first on
/// PYTHONPATH.
std::string python_command(const std::string& arguments);

/// Draws `python3 -m shockfield_plot KIND CSV PNG` (shockfield_plot/__main__.py); true when the PNG
/// was written. A missing interpreter or a failing helper is a warning on stderr (the CSV stays the
/// result), never an error.
bool plot_csv(const std::string& kind, const std::filesystem::path& csv, const std::filesystem::path& png);

/// `text` single-quoted for a POSIX shell.
std::string shell_quote(const std::string& text);

}  // namespace shockfield::app
