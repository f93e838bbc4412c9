// `shockfield plot KIND RUN [options]`: PNG figures of a run folder. The command is the Python
// package's: every argument (--help included) goes to `python -m shockfield.plot`
// (python/shockfield/plot, which lists the kinds and draws them through shockfield_plot), found
// and run as app/python_helpers.hpp says; its exit code is the command's (2: bad input, e.g. a
// kind the run does not have).
#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>

#include "shockfield/app/commands.hpp"
#include "shockfield/app/python_helpers.hpp"

namespace shockfield::app {
namespace {

void plot(const std::vector<std::string>& arguments) {
  std::string args = "-m shockfield.plot";
  for (const std::string& a : arguments) args += " " + shell_quote(a);
  const std::string command = "SHOCKFIELD_PROG='shockfield plot' " + python_command(args);
  std::fflush(stdout);
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (code != 0) std::exit(code);  // the package printed its message
}

}  // namespace

void add_plot_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw a PNG figure of a run folder: shockfield plot KIND RUN [-o PNG]. `shockfield plot --help`\n"
      "lists every kind (thermo, series, profiles, tne, phase-separation, chain, ...); the command runs\n"
      "`python -m shockfield.plot` with the same arguments (docs/python.md, Figures).");
  cmd->set_help_flag();  // --help is the package's
  cmd->prefix_command();
  cmd->callback([cmd] { plot(cmd->remaining()); });
}

}  // namespace shockfield::app
