#pragma once
// `shockfield sweep` (sweep_command.cpp): the Python package's shockfield.sweep behind a subcommand.
#include <CLI/CLI.hpp>

namespace shockfield::app {

void add_sweep_command(CLI::App& app);

}  // namespace shockfield::app
