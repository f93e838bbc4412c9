#pragma once
// MD checkpoints (HDF5): everything the time loop needs to continue as if never stopped —
// atoms (positions, velocities, image counts, ids, types, groups), box, clock, the positions and
// box of the last neighbour-list build (so the resumed run rebuilds the identical list and sums
// forces in the identical order: bitwise restart with the same thread count), the fixes' state
// and where in the stage list the run was. Written through
// io/checkpoint_file: checksummed, verified, then renamed; read only after its checksum matches.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

/// The layout (docs/checkpoints.md), md and macroparticle. 2: self-describing (named datasets with
/// units, integer counters, type masses and names); 3: each fix variable a dataset of its own
/// (fix<k>_<fix>.<variable>, was one `mixed` array per fix).
inline constexpr std::int64_t kCheckpointFormat = 3;

struct CheckpointPosition {
  std::int64_t stage = 0;        ///< index in the case's [[stage]] list
  std::int64_t stage_step = 0;   ///< steps done in that stage
};

/// The method and unit labels a checkpoint of the MD engine carries: LAMMPS metal units for md,
/// the engine's reduced units for the macroscopic particles (macroparticle/reduced_units.hpp).
struct CheckpointUnits {
  std::string method = "md", system = "metal", length = "Angstrom", velocity = "Angstrom/ps", force = "eV/Angstrom",
              mass = "g/mol";
  bool metal_fix_units = true;  ///< the fixes' variables labelled in metal units (else "1")
};

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const CheckpointPosition& where,
                      const CheckpointUnits& units = {});

/// Where in the stage list the checkpointed run was.
CheckpointPosition read_checkpoint_header(const std::filesystem::path& file, const std::string& method = "md");
/// Restores `sim` (built from the same case file, with the fixes of the checkpoint's stage
/// already added), ready for its next step: forces as they were (fix contributions included),
/// energy and virial recomputed. Throws InputError when the checkpoint does not fit the case.
void read_checkpoint(const std::filesystem::path& file, Simulation& sim, const std::string& method = "md");

}  // namespace shockfield::md
