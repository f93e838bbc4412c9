// shockfield: the command-line front end. Subcommands live in one file each (see commands.hpp).
#include <fmt/format.h>

#include <cstdio>
#include <new>

#include "shockfield/app/commands.hpp"
#include "shockfield/app/sweep_command.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/parallel/communicator.hpp"

int main(int argc, char** argv) {
  // MPI (when built) for the whole program; ranks other than 0 print nothing (docs/parallel.md).
  const shockfield::parallel::Environment mpi(argc, argv);
  CLI::App app{
      "shockfield " SHOCKFIELD_VERSION
      " - shock response of heterogeneous materials, from atoms to the sample.\n"
      "Simulate with molecular dynamics (md), the material point method (mpm), peridynamics (pd);\n"
      "analyse the fields, atoms and point sets that come out (analyze); sweep shock Hugoniots\n"
      "(hugoniot); run a case for several values of its keys (sweep); carry what one scale measured\n"
      "to the next as a material file (bridge); turn a run's checkpoint into a LAMMPS data file or\n"
      "VTK file (convert). `--version` names the build.\n"
      "Run `shockfield SUBCOMMAND --help` for each subcommand's options.",
      "shockfield"};
  app.require_subcommand(1);
  app.set_version_flag("--version", shockfield::app::version_text,
                       "Print the version, git commit, compiler and library versions, then exit");
  shockfield::app::add_run_command(app, std::vector<std::string>(argv, argv + argc));
  shockfield::app::add_plot_command(app);
  shockfield::app::add_hugoniot_command(app);
  shockfield::app::add_analyze_command(app);
  shockfield::app::add_sweep_command(app);
  shockfield::app::add_convert_command(app);
  shockfield::app::add_bridge_command(app, std::vector<std::string>(argv, argv + argc));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error (unknown option, missing or malformed
    // value, a file that does not exist) is exit 2 like any other input error, not CLI11's
    // own codes (105, 106, 109, ...).
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const shockfield::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const shockfield::StopRequested& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 130;
  } catch (const shockfield::RunError& e) {
    std::fprintf(stderr, "run stopped: %s\n", e.what());
    return 3;
  } catch (const std::bad_alloc&) {
    // A case asking for more than the machine has (the counts themselves are bounded where they
    // are read): a run-time failure with a reason, not a bare "std::bad_alloc".
    std::fprintf(stderr, "run stopped: out of memory: the case needs more memory than is available "
                         "(reduce the grid, the sample or the particle count, or use a larger machine)\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
