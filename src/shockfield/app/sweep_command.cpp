// `shockfield sweep CASE --set key=v1,v2,... [-j N] -o DIR`: the case run for every combination
// of the values, side by side, with a table of their summary.json results. The sweep itself is
// the Python package's (`python -m shockfield sweep`, shockfield/sweep.py: it runs `shockfield
// run` per combination and reads each summary.json), started through app/python_helpers.hpp.
#include "shockfield/app/sweep_command.hpp"

#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "shockfield/app/python_helpers.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {
namespace {

struct SweepOptions {
  std::string case_file, output;
  std::vector<std::string> sets;
  int jobs = 1, threads = 1;
  bool overwrite = false;
};

void sweep(const SweepOptions& o) {
  std::string args = fmt::format("-m shockfield sweep {} -o {} -j {} --threads {}", shell_quote(o.case_file),
                                 shell_quote(o.output), o.jobs, o.threads);
  for (const auto& s : o.sets) args += " --set " + shell_quote(s);
  if (o.overwrite) args += " --overwrite";
  // The package finds this very command through SHOCKFIELD_BIN.
  const std::string command = fmt::format("SHOCKFIELD_BIN={} {}", shell_quote(std::filesystem::read_symlink("/proc/self/exe").string()), python_command(args));
  std::fflush(stdout);
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (code != 0) std::exit(code);  // the sweep printed its message (exit 2: a bad key or value)
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run a case for every combination of values, side by side, into one folder.\n"
      "Each --set KEY=V1,V2,... (TOML values, as for `run --set`) adds a swept key; every\n"
      "combination is checked before anything runs (a bad key or value: exit 2 naming it). The\n"
      "runs go to DIR/KEY=VALUE[,...]; DIR/sweep.csv (also printed) holds one row per run with the\n"
      "values, status, steps, wall time and the results of its summary.json (docs/python.md).");
  cmd->add_option("case", o->case_file, "Case file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--set", o->sets, "KEY=V1,V2,...: the values of one swept key; repeatable")
      ->required()
      ->type_name("KEY=V1,V2,...")
      ->allow_extra_args(false);
  cmd->add_option("-o,--output", o->output, "Folder of the sweep")->required();
  cmd->add_option("-j,--jobs", o->jobs, "Runs at the same time")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o->threads, "OpenMP threads per run")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_flag("--overwrite", o->overwrite, "Replace existing run folders");
  cmd->callback([o] { sweep(*o); });
}

}  // namespace shockfield::app
