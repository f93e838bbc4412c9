#pragma once
// The `shockfield` subcommands. Each add_*_command() attaches one subcommand (with its complete
// --help) to the application; main() calls them in order. A subcommand's callback returns through
// exceptions: InputError and RunError become one message on stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shockfield::app {

/// `command_line` is the program's argv, recorded in each run's provenance.
void add_run_command(CLI::App& app, const std::vector<std::string>& command_line);
void add_plot_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
/// `analyze atoms`, attached to the analyze subcommand by add_analyze_command.
void add_analyze_atoms_command(CLI::App& analyze);
void add_hugoniot_command(CLI::App& app);
void add_analyze_geometry_command(CLI::App& analyze);
/// What `shockfield --version` prints: version, git commit, compiler and library versions.
std::string version_text();

}  // namespace shockfield::app
