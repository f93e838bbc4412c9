#pragma once
// The fuzz targets: each is a set of valid inputs and the way one input file is put through
// shockfield — the parsers in-process (dump and field files, in a fork: sandbox.hpp) or the
// `shockfield` binary (case files, potential and data files through a short MD run, checkpoints
// through --resume), as a user would meet them.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sandbox.hpp"

namespace shockfield::fuzz {

struct Context {
  std::filesystem::path source;      ///< the source tree (fixtures, examples)
  std::filesystem::path shockfield;  ///< the shockfield binary
  std::filesystem::path work;        ///< scratch folder of this fuzz run
  Limits limits;
};

struct Target {
  std::string name;
  std::vector<std::filesystem::path> inputs;  ///< valid inputs to mutate
  bool binary = false;                        ///< mutate as bytes (no number tokens)
  bool with_siblings = false;  ///< the input's folder neighbours are linked next to a mutant
  /// The case file that carries the input into the run (potential, data and checkpoint
  /// targets): an input error may name it (with the key) instead of the input itself.
  std::string carrier;
  /// Puts `file` (a mutant or a corpus entry, named as its input) through shockfield, in `work`.
  std::function<Outcome(const std::filesystem::path& file, const std::filesystem::path& work)> run;
};

/// The targets `names` selects (all when empty): with a shockfield binary (Context::shockfield)
/// every parser, through the binary or in-process; without one the parsers alone, in-process
/// (the sanitized parser-only driver of CI). Throws std::runtime_error naming a missing input,
/// or an unknown target unless `skip_unknown`.
std::vector<Target> make_targets(const Context& context, const std::vector<std::string>& names,
                                 bool skip_unknown = false);

}  // namespace shockfield::fuzz
