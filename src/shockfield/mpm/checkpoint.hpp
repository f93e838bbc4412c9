#pragma once
// MPM checkpoints (HDF5): every particle array and constitutive state, the clock, the output
// counters and the cavity tracker, so that a resumed run continues bitwise as if never stopped
// (same thread count; the solver keeps no other state between steps). Written through
// io/checkpoint_file: checksummed, verified, then renamed; read only after its checksum matches.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "shockfield/mpm/simulation.hpp"

namespace shockfield::mpm {

/// The layout (docs/checkpoints.md). 2: damage added; 3: self-describing (one dataset per
/// quantity with units, integer counters).
inline constexpr std::int64_t kCheckpointFormat = 3;

/// How far the driver's output schedule had got.
struct OutputCounters {
  std::int64_t series = 0;      ///< series rows written (row k at k·series_interval)
  std::int64_t fields = 0;      ///< field frames written
  std::int64_t histograms = 0;  ///< histogram times done
};

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>& cavity_state);

/// Restores the particles and clock of `sim` (built from the same case file) and returns the
/// counters; `cavity_state` receives the tracker state (empty when none was saved). InputError
/// when the checkpoint does not fit the case.
OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>& cavity_state);

}  // namespace shockfield::mpm
