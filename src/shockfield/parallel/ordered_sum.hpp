#pragma once
// Sums whose bits do not depend on how the items are shared among ranks (docs/parallel.md): every
// rank's per-item values are gathered, put in global item order, and added in that order — the
// order a one-rank run adds them in — on every rank. Floating-point addition is not associative,
// so an MPI_Allreduce of per-rank partial sums would change in the last bits with the rank grid.
// Meant for per-row or per-particle partials (thermo, series means), not per-cell fields.
#include <vector>

#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

/// Σ over all items of all ranks, in global index order, of `columns` quantities: this rank's
/// item n has global index `index[n]` (0 ≤ index < the total item count, each index held by one
/// rank) and values values[n·columns + q]. The same result on every rank. Collective.
std::vector<double> ordered_sum(const Communicator& comm, const std::vector<double>& values,
                                const std::vector<long long>& index, int columns);

}  // namespace shockfield::parallel
