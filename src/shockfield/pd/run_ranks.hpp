#pragma once
// `shockfield run` of a pd case under mpirun (docs/parallel.md, "Peridynamics under mpirun"):
// whether the body is decomposed, the refusal before the run of what is not, and moving the state
// between the whole body (every rank builds it; rank 0 writes every output from it) and a rank's
// points (decomposition.hpp).
//
// Model state arrays (model_state.hpp) are per bond when their name begins with "bond_"
// (BondForce's bond_intact), else per point (critical_stretch): a bond's entry travels with the
// point whose family lists it, so the flag of bond i→j is owned and decided on i's rank.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/pd/case_file.hpp"
#include "shockfield/pd/decomposition.hpp"
#include "shockfield/pd/model_state.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

/// The decomposition of a run started by mpirun on more than one rank, or given --rank-grid; null
/// for a serial run. Collective over the world's ranks. InputError (the same on every rank, before
/// the run) naming the key of what is not decomposed — a correspondence model (`material.model`
/// j2 or crystal), the contact force (`material.contact`), a [homogeneous] case is refused by the
/// caller — or the rank grid's refusal (more ranks than the body can be cut into for δ).
std::shared_ptr<Decomposition> decompose_run(const Config& root, const PdCase& c, const PointCloud& cloud,
                                             const Family& family, const RunOptions& options);

/// Each local point's and bond's share of the whole body's model state.
ModelState local_state(const Decomposition& domain, const ModelState& whole);

/// The local points' positions, velocities and force densities and the clock from the whole
/// body's `whole` into `local` (the first step then continues bitwise).
void deal_out(const Decomposition& domain, const Simulation& whole, Simulation& local);

/// Every rank's owned points (state, force densities, clock) and their model state gathered on
/// rank 0 into `whole` and `whole_state` (which holds the whole body's arrays, overwritten);
/// nothing changes elsewhere. A point arriving twice or not at all ends every rank (exit 3).
/// Collective.
void gather_whole(const Decomposition& domain, const Simulation& local, const ModelState& local_state,
                  Simulation& whole, ModelState& whole_state);

}  // namespace shockfield::pd
