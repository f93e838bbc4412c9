#pragma once
// `shockfield run` of an MD case under mpirun (docs/parallel.md, "MD under mpirun"): whether the
// case's box is decomposed over the ranks, and the refusal, before the run, of what is not.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/decomposition.hpp"

namespace shockfield::md {

/// The rank grid of a run started by mpirun on more than one rank, or given --rank-grid; null for
/// a serial run. Collective over the world's ranks. InputError (the same on every rank, before the
/// run) naming the key of anything the decomposed Simulation does not do: an ensemble other than
/// nve, nvt or langevin (minimize, npt, msst, nphug), a piston, deform, a box that is not periodic
/// along x, y and z or is triclinic, and the outputs that need every atom's per-atom energy on one
/// rank (profiles, [analysis], H5MD, pe and stress dump columns); or the rank grid's refusal.
std::shared_ptr<Decomposition> decompose_run(const Config& root, const MdCase& md, const geometry::Box& box,
                                             double interaction_range, const RunOptions& options);

}  // namespace shockfield::md
