#pragma once
// PD checkpoints (HDF5): positions, velocities, the force density of the last evaluation, the
// force model's saved state (one dataset per quantity: broken bonds and critical stretches, or F
// and the material state per point; model_state.hpp), the clock and the output counters,
// so that a resumed run continues bitwise as if never stopped (same thread count). Written through
// io/checkpoint_file: checksummed, verified, then renamed; read only after its checksum matches.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "shockfield/pd/model_state.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

/// The layout (docs/checkpoints.md). 2: self-describing (named datasets with units, integer
/// counters); 3: the force model's state as one named dataset per quantity (was `model_state`).
inline constexpr std::int64_t kCheckpointFormat = 3;

/// How far the driver's output schedule had got.
struct OutputCounters {
  std::int64_t series = 0;    ///< series rows written (row k at k·series_interval)
  std::int64_t profiles = 0;  ///< profiles written
};

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const ModelState& model_state,
                      const OutputCounters& counters);

/// Restores `sim` (built from the same case file) and returns the counters; `model_state`
/// receives the force model's state (every dataset besides the simulation's own). InputError
/// when the checkpoint does not fit the case.
OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, ModelState& model_state);

}  // namespace shockfield::pd
