#pragma once
// The interiors of every rank's block of a structured grid collected into the whole grid on rank
// 0, and the whole grid dealt back out: how a distributed method hands its state to the serial
// output, checkpoint and initial-state code, which then run unchanged on rank 0 (docs/parallel.md:
// not parallel I/O — rank 0 holds the whole grid).
#include "shockfield/parallel/grid_layout.hpp"
#include "shockfield/parallel/rank_grid.hpp"

namespace shockfield::parallel {

/// Every rank's interior cells of `local_data` (layout `local`) into `global_data` (layout
/// `global`, the whole grid; written on rank 0 only, may be null elsewhere). Collective.
void gather_blocks(const RankGrid& grid, const GridLayout& local, const double* local_data, const GridLayout& global,
                   double* global_data);
/// The inverse: each rank's interior cells of `local_data` from rank 0's `global_data`. Collective.
void scatter_blocks(const RankGrid& grid, const GridLayout& global, const double* global_data,
                    const GridLayout& local, double* local_data);

}  // namespace shockfield::parallel
