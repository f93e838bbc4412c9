#pragma once
// The `shockfield` subcommands. Each add_*_command() attaches one subcommand (with its complete
// --help) to the application; main() calls them in order. A subcommand's callback returns through
// exceptions: InputError and RunError become one message on stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <filesystem>
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
void add_convert_command(CLI::App& app);
void add_analyze_geometry_command(CLI::App& analyze);
/// What `shockfield --version` prints: version, git commit, compiler and library versions.
std::string version_text();
/// `bridge` and its subcommands, one file each (bridge_<name>_command.cpp), attached by
/// add_bridge_command; `command_line` goes into the written material file's provenance.
void add_bridge_command(CLI::App& app, const std::vector<std::string>& command_line);
/// The options every bridge shares: -o FILE, --update (replacing only `sections`), --name.
struct BridgeOutput {
  std::filesystem::path file;
  bool update = false;
  std::string name = "md";
};
void add_bridge_output_options(CLI::App& bridge_subcommand, BridgeOutput& out, const std::string& sections);
void add_bridge_hugoniot_to_eos_command(CLI::App& bridge, const std::vector<std::string>& command_line);
void add_bridge_elastic_command(CLI::App& bridge, const std::vector<std::string>& command_line);
void add_bridge_eam_to_macroparticle_command(CLI::App& bridge, const std::vector<std::string>& command_line);
void add_bridge_spall_command(CLI::App& bridge, const std::vector<std::string>& command_line);
void add_bridge_yield_command(CLI::App& bridge, const std::vector<std::string>& command_line);
void add_bridge_domain_growth_command(CLI::App& bridge, const std::vector<std::string>& command_line);

}  // namespace shockfield::app
