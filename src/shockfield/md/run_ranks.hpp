#pragma once
// `shockfield run` of an MD case under mpirun (docs/parallel.md, "MD under mpirun"): whether the
// case's box is decomposed over the ranks, and the refusal, before the run, of what is not.
#include <memory>
#include <optional>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

/// The rank grid of a run started by mpirun on more than one rank, or given --rank-grid; null for
/// a serial run. Collective over the world's ranks. InputError (the same on every rank, before the
/// run) naming the key of anything the decomposed Simulation does not do: an ensemble other than
/// nve, nvt or langevin (minimize, npt, msst, nphug), a piston, deform, a box that is not periodic
/// along x, y and z or is triclinic, and the outputs that need every atom's per-atom energy on one
/// rank (profiles, [analysis], H5MD, pe and stress dump columns); or the rank grid's refusal.
std::shared_ptr<Decomposition> decompose_run(const Config& root, const MdCase& md, const geometry::Box& box,
                                             double interaction_range, const RunOptions& options);

/// A resumed decomposed run, the whole checkpoint read into `sim` on every rank: keeps the atoms
/// of this rank's piece and lists them where the last rebuild saw them, as the serial restore
/// does (Simulation::restore_rebuild_state), so that the resumed run rebuilds at the steps the
/// uninterrupted one does; then the current positions, the energies of the restored step and the
/// saved forces (a Langevin step's include the bath's). Collective; sim.domain is set.
void deal_out_checkpoint(Simulation& sim, const std::shared_ptr<Decomposition>& domain);

/// Every rank's atoms of the decomposed `sim` on rank 0 as a Simulation of its own (no potential,
/// no fixes) for the serial checkpoint writer, with their forces, clock, rebuild count and
/// positions at the last rebuild, in id order; nothing on the other ranks. Collective.
std::optional<Simulation> gather_simulation(const Simulation& sim);

}  // namespace shockfield::md
