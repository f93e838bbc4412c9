#pragma once
// The Cartesian rank grid of a structured grid of cells (docs/parallel.md): how many ranks along
// each axis, which block of cells each rank owns, and its neighbours. The same grid serves every
// grid method (DBM today; MPM's background grid and phase field later).
#include <array>
#include <string>

#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

using Cells3 = std::array<long long, 3>;
using Dims3 = std::array<int, 3>;

/// The cells [begin, begin + count) along each axis owned by one rank.
struct Block {
  Cells3 begin{0, 0, 0}, count{1, 1, 1};
};

/// Part `index` of `n` cells cut into `parts` as evenly as possible (sizes differ by at most 1;
/// part p begins at ⌊p·n/parts⌋).
Block split_axis(long long n, int parts, int index);

/// The rank grid for `ranks` ranks over `cells` that needs the least halo traffic per block (the
/// sum over cut axes of the block's two faces) with every block at least `min_cells` cells along
/// each cut axis (the stencil's ghost width). InputError when no grid fits, naming the largest
/// rank count that does.
Dims3 choose_rank_grid(const Cells3& cells, int ranks, int min_cells);

/// InputError unless `dims` (as given by the user) has `ranks` ranks and cuts no axis into blocks
/// of fewer than `min_cells` cells.
void check_rank_grid(const Dims3& dims, const Cells3& cells, int ranks, int min_cells);

/// The rank grid of `--rank-grid`: "PxQ" or "PxQxR" (R = 1 when left out); InputError otherwise.
Dims3 parse_rank_grid(const std::string& text);

class RankGrid {
 public:
  /// A collective call on `world`: MPI_Cart_create of dims (checked by check_rank_grid).
  RankGrid(const Communicator& world, const Dims3& dims, const std::array<bool, 3>& periodic, const Cells3& cells,
           int min_cells);

  const Communicator& comm() const { return comm_; }
  const Dims3& dims() const { return dims_; }
  const Cells3& cells() const { return cells_; }
  /// The block of this rank, and of any rank of the grid.
  const Block& block() const { return block_; }
  Block block_of(int rank) const;

 private:
  Communicator comm_;
  Dims3 dims_;
  Cells3 cells_;
  Block block_;
};

}  // namespace shockfield::parallel
