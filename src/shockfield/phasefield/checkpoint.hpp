#pragma once
// Phase-field checkpoints (HDF5, io/hdf5_file): ξ, the clock and the output counters — all a step
// needs — so a resumed run continues bitwise. Written to a temporary file and renamed.
#include <cstdint>
#include <filesystem>

#include "shockfield/phasefield/solver.hpp"

namespace shockfield::phasefield {

/// The layouts (docs/checkpoints.md). Phase field 2: checksummed (io/checkpoint_file); 3:
/// self-describing (units, integer counters, dim and dx). Sharp front 2: self-describing (one
/// dataset per domain quantity, integer counters and tracks).
inline constexpr std::int64_t kCheckpointFormat = 3;
inline constexpr std::int64_t kSharpFrontCheckpointFormat = 2;

struct OutputCounters {
  std::int64_t series = 0;  ///< series rows written (row k at k·series_interval)
  std::int64_t frames = 0;  ///< field frames written
};

void write_checkpoint(const std::filesystem::path& file, const Solver& solver, const OutputCounters& counters);
/// Restores ξ and the clock; InputError when the checkpoint does not fit the case's grid.
OutputCounters read_checkpoint(const std::filesystem::path& file, Solver& solver);

}  // namespace shockfield::phasefield
