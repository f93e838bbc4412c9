#pragma once
// Options of `shockfield run` that are not part of the case file.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shockfield {

struct RunOptions {
  std::filesystem::path case_file;
  std::optional<std::filesystem::path> output;   ///< run folder; default runs/<case name>
  bool overwrite = false;                        ///< replace an existing run folder
  bool resume = false;                           ///< continue from the folder's last checkpoint
  int threads = 0;                               ///< OpenMP threads; 0 = OMP_NUM_THREADS or all cores
  bool quiet = false;                            ///< no progress line
  bool validate_only = false;                    ///< check the case file and stop
  long long stop_after = 0;                      ///< stop as on Ctrl-C after this many steps (0: never)
  std::string rank_grid;                         ///< --rank-grid PxQ[xR]: the MPI rank grid; empty: chosen
  std::optional<double> piston_speed;            ///< Å/ps: replaces the speed of every [stage.piston]
  std::vector<std::string> overrides;            ///< --set KEY=VALUE, in command-line order
  std::vector<std::string> command_line;         ///< argv of the program, for provenance
};

}  // namespace shockfield
