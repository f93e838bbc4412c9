// `shockfield run CASE.toml`: validates the case file, then runs the method it names.
#include <fmt/format.h>
#include <omp.h>

#include <map>

#include "shockfield/app/commands.hpp"
#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/dbm/run_case.hpp"
#include "shockfield/md/run_case.hpp"
#include "shockfield/pd/run_case.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/parallel/communicator.hpp"
#include "shockfield/registry/method_registry.hpp"

namespace shockfield::app {
namespace {

// The methods whose lattice or box is decomposed over MPI ranks (docs/parallel.md), with what the
// ranks other than 0 run: rank 0 runs the driver as in a serial run and drives them.
using RankServer = void (*)(const Config&, const RunOptions&);
const std::map<std::string, RankServer>& decomposed_methods() {
  static const std::map<std::string, RankServer> table{{"dbm", &dbm::serve_ranks}, {"md", &md::serve_ranks}, {"pd", &pd::serve_ranks}};
  return table;
}

// `resolved_file`: with --check, where the resolved case (every value read, defaults and
// [derived]) goes, as config.resolved.toml would hold it (the Python module's Case.check()).
void run(const RunOptions& options, const std::string& resolved_file) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const Config root = Config::load(options.case_file, options.overrides);
  const MethodFactory& factory = method_factory(root);  // validates `method`
  const parallel::Communicator world = parallel::Communicator::world();
  if (world.size() > 1 || !options.rank_grid.empty()) {
    const std::string method = root.get_string("method");
    const auto server = decomposed_methods().find(method);
    if (server == decomposed_methods().end())
      throw InputError(fmt::format("{}: method '{}' runs on one rank only so far ({} ranks started{}); run it "
                                   "without mpirun; docs/parallel.md lists the decomposed methods",
                                   options.case_file.string(), method, world.size(),
                                   options.rank_grid.empty() ? "" : ", --rank-grid given"));
    if (!world.is_root()) return server->second(root, options);
  }
  run_method(root, options, factory);
  if (!resolved_file.empty()) io::replace_file(resolved_file, root.resolved_toml());
}

}  // namespace

void add_run_command(CLI::App& app, const std::vector<std::string>& command_line) {
  auto options = std::make_shared<RunOptions>();
  options->command_line = command_line;
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Run a simulation described by a TOML case file.\n"
      "The case file is checked completely before anything runs (unknown keys, wrong types,\n"
      "missing or out-of-range values are reported with file, key and line). The run writes a\n"
      "folder with log.txt, config.resolved.toml, thermo.csv, dumps and checkpoints.\n"
      "Ctrl-C or SIGTERM writes a checkpoint and stops; --resume continues from it.\n"
      "Case-file keys: docs/md.md (method = \"md\"), docs/mpm.md (\"mpm\"), docs/pd.md (\"pd\"),\n"
      "docs/dbm.md (\"dbm\"), docs/granular.md (\"granular\"), docs/phasefield.md (\"phasefield\"),\n"
      "docs/macroparticle.md (\"macroparticle\").");
  cmd->add_option("case", options->case_file, "Case file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "Run folder (default: runs/<case file name without .toml>; a case.toml is named\n"
                  "by its folder: examples/md_shock_piston/case.toml -> runs/md_shock_piston)");
  cmd->add_flag("--overwrite", options->overwrite, "Replace an existing run folder");
  cmd->add_flag("--resume", options->resume,
                "Continue the run in the output folder from its last checkpoint");
  cmd->add_option("-j,--threads", options->threads,
                  "OpenMP threads (default: OMP_NUM_THREADS, else all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("-q,--quiet", options->quiet, "No progress line");
  cmd->add_option("--rank-grid", options->rank_grid,
                  "MPI ranks along x, y (and z) as PxQ or PxQxR, their product the rank count\n"
                  "(mpirun -np); default: the grid with the least halo traffic (dbm, md and pd;\n"
                  "docs/parallel.md)")
      ->type_name("PxQ");
  cmd->add_option("--stop-after", options->stop_after,
                  "Stop after this many steps as Ctrl-C would (checkpoint, exit code 130)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--set", options->overrides,
                  "Set a case-file value, as if edited in the file: --set KEY=VALUE with a dotted\n"
                  "key (md.timestep, stage[1].steps) and a TOML value (1.5, 10, true, '\"text\"',\n"
                  "[1, 2]); repeatable; checked like the file's, recorded in config.resolved.toml\n"
                  "(docs/run-inputs.md)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  cmd->add_flag("--check", options->validate_only,
                "Only validate the case file (and the files it names), then exit");
  auto resolved_file = std::make_shared<std::string>();
  cmd->add_option("--write-resolved", *resolved_file,
                  "With --check: write the resolved case (defaults and [derived] included) to this file")
      ->needs("--check");
  cmd->callback([options, resolved_file] { run(*options, *resolved_file); });
}

}  // namespace shockfield::app
