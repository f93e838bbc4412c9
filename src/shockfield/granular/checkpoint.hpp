#pragma once
// Granular checkpoints (HDF5, io/hdf5_file.hpp): displacements, velocities, the grain and contact
// forces of the last evaluation, the clock, the force history's work and the output counters, so
// that a resumed run continues bitwise as if never stopped. Written to a temporary file and
// renamed.
#include <cstdint>
#include <filesystem>

#include "shockfield/granular/simulation.hpp"

namespace shockfield::granular {

/// The layout (docs/checkpoints.md). 2: checksummed (io/checkpoint_file); 3: the profiles counter;
/// 4: self-describing (units, integer counters, the chain's depth, radius and mass).
inline constexpr std::int64_t kCheckpointFormat = 4;

/// How far the output schedule had got.
struct OutputCounters {
  std::int64_t series = 0;     ///< thermo rows written
  std::int64_t probes = 0;     ///< probe rows written
  std::int64_t spacetime = 0;  ///< space–time rows written
  std::int64_t signal = 0;     ///< signal measurements written
  std::int64_t profiles = 0;   ///< particle frames written
};

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters);

/// Restores `sim` (built from the same case) and returns the counters. InputError when the
/// checkpoint does not fit the case.
OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim);

}  // namespace shockfield::granular
