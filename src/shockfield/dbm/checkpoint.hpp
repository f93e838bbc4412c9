#pragma once
// DBM checkpoints (HDF5): the distributions f, the clock and the output counters, so that a
// resumed run continues bitwise as if never stopped (same thread count; the model keeps no other
// state between steps). Written through
// io/checkpoint_file: checksummed, verified, then renamed; read only after its checksum matches.
#include <cstdint>
#include <filesystem>

#include "shockfield/dbm/simulation.hpp"

namespace shockfield::dbm {

/// The layout (docs/checkpoints.md). 2: self-describing (units, integer counters, the lattice's
/// shape and the velocity model).
inline constexpr std::int64_t kCheckpointFormat = 2;

/// How far the driver's output schedule had got.
struct OutputCounters {
  std::int64_t series = 0;    ///< series rows written (row k at k·series_interval)
  std::int64_t profiles = 0;  ///< scheduled profiles written
  std::int64_t fields = 0;    ///< field frames written
};

/// `reactant`: the reactant density φ of a reactive case (reaction.hpp), stored beside f.
void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>* reactant = nullptr);

/// Restores f and the clock of `sim` (built from the same case file), and φ into `reactant` when
/// given, and returns the counters. InputError when the checkpoint does not fit the case.
OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim,
                               std::vector<double>* reactant = nullptr);

}  // namespace shockfield::dbm
