// `shockfield bridge SUBCOMMAND`: what one scale learns becomes the next scale's material (Xu et
// al. 2015, §1, §5). Each bridge is one file, app/bridge_<name>_command.cpp, with one
// add_bridge_<name>_command() that attaches its subcommand here; each reads run folders or
// results of one scale and writes a material file with [provenance] (docs/materials.md,
// docs/bridges.md).
#include "shockfield/app/commands.hpp"

namespace shockfield::app {

void add_bridge_output_options(CLI::App& cmd, BridgeOutput& out, const std::string& sections) {
  cmd.add_option("-o,--output", out.file, "Material file to write (TOML)")->required();
  cmd.add_flag("--update", out.update, "Write into an existing material file, replacing only its " + sections);
  cmd.add_option("--name", out.name, "The material's name in the file")->capture_default_str();
}

void add_bridge_command(CLI::App& app, const std::vector<std::string>& command_line) {
  CLI::App* bridge = app.add_subcommand(
      "bridge",
      "Scale bridges: fit what a run of one scale measured and write it as a material file for the\n"
      "next scale (docs/bridges.md). Each subcommand writes a TOML material file whose\n"
      "[provenance.<bridge>] names the command, its inputs (with the SHA-256 of their resolved\n"
      "configurations) and the fit with its uncertainty; MPM ([[material]] file = ...), PD and\n"
      "macroparticle ([material] file = ...) cases read it (docs/materials.md). --update writes\n"
      "into an existing file, replacing only the sections this bridge gives.");
  bridge->require_subcommand(1);
  add_bridge_hugoniot_to_eos_command(*bridge, command_line);
  add_bridge_elastic_command(*bridge, command_line);
  add_bridge_eam_to_macroparticle_command(*bridge, command_line);
  add_bridge_spall_command(*bridge, command_line);
  add_bridge_yield_command(*bridge, command_line);
  add_bridge_domain_growth_command(*bridge, command_line);
}

}  // namespace shockfield::app
