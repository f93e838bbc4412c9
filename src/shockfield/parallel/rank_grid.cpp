#include "shockfield/parallel/rank_grid.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <limits>

#include "shockfield/core/error.hpp"

namespace shockfield::parallel {
namespace {

// The most blocks an axis of n cells can be cut into (an axis of one cell is never cut).
long long max_parts(long long n, int min_cells) { return n == 1 ? 1 : n / min_cells; }

std::string grid_text(const Cells3& c) { return fmt::format("{} x {} x {}", c[0], c[1], c[2]); }

// Ghost cells a block exchanges per layer: its two faces on each cut axis (the largest block).
double halo_faces(const Cells3& cells, const Dims3& dims) {
  double faces = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (dims[a] == 1) continue;
    double face = 2.0;
    for (int b = 0; b < 3; ++b)
      if (b != a) face *= static_cast<double>((cells[b] + dims[b] - 1) / dims[b]);
    faces += face;
  }
  return faces;
}

}  // namespace

Block split_axis(long long n, int parts, int index) {
  Block b;
  b.begin[0] = n * index / parts;
  b.count[0] = n * (index + 1) / parts - b.begin[0];
  return b;
}

Dims3 choose_rank_grid(const Cells3& cells, int ranks, int min_cells) {
  Dims3 best{0, 0, 0};
  double best_faces = std::numeric_limits<double>::infinity();
  for (int d0 = 1; d0 <= ranks; ++d0) {
    if (ranks % d0 != 0 || d0 > max_parts(cells[0], min_cells)) continue;
    for (int d1 = 1; d1 <= ranks / d0; ++d1) {
      if ((ranks / d0) % d1 != 0 || d1 > max_parts(cells[1], min_cells)) continue;
      const int d2 = ranks / d0 / d1;
      if (d2 > max_parts(cells[2], min_cells)) continue;
      const double faces = halo_faces(cells, {d0, d1, d2});
      if (faces < best_faces) best = {d0, d1, d2}, best_faces = faces;
    }
  }
  if (best[0] == 0) {
    long long most = 1;
    for (long long n : cells) most *= max_parts(n, min_cells);
    throw InputError(fmt::format(
        "{} ranks cannot share a {} grid: each rank needs at least {} cells along every cut axis (the "
        "stencil's ghost layers); use at most {} ranks, or a rank count that factors onto the grid",
        ranks, grid_text(cells), min_cells, most));
  }
  return best;
}

void check_rank_grid(const Dims3& dims, const Cells3& cells, int ranks, int min_cells) {
  const long long product = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || product != ranks)
    throw InputError(fmt::format("--rank-grid {} x {} x {} has {} ranks, the run has {} (mpirun -np): the "
                                 "product of the rank grid must be the rank count",
                                 dims[0], dims[1], dims[2], product, ranks));
  constexpr const char* axis_name = "xyz";
  for (int a = 0; a < 3; ++a)
    if (dims[a] > max_parts(cells[a], min_cells))
      throw InputError(fmt::format("--rank-grid cuts {} ({} cells) into {} blocks: at most {} fit, each needs "
                                   "at least {} cells (the stencil's ghost layers)",
                                   axis_name[a], cells[a], dims[a], max_parts(cells[a], min_cells), min_cells));
}

Dims3 parse_rank_grid(const std::string& text) {
  Dims3 dims{1, 1, 1};
  char x1 = 0, x2 = 0, rest = 0;
  const int read = std::sscanf(text.c_str(), "%d%c%d%c%d%c", &dims[0], &x1, &dims[1], &x2, &dims[2], &rest);
  const bool ok = (read == 3 && x1 == 'x') || (read == 5 && x1 == 'x' && x2 == 'x');
  if (!ok || dims[0] < 1 || dims[1] < 1 || dims[2] < 1)
    throw InputError(fmt::format("--rank-grid '{}': expected the ranks along x, y (and z) as PxQ or PxQxR, "
                                 "each at least 1 (e.g. 2x2)", text));
  return dims;
}

RankGrid::RankGrid(const Communicator& world, const Dims3& dims, const std::array<bool, 3>& periodic,
                   const Cells3& cells, int min_cells)
    : comm_((check_rank_grid(dims, cells, world.size(), min_cells), world.cartesian(dims, periodic))),
      dims_(dims),
      cells_(cells),
      block_(block_of(comm_.rank())) {}

Block RankGrid::block_of(int rank) const {
  // MPI's Cartesian ranks are row-major: the last axis varies fastest.
  const Dims3 coords{rank / (dims_[1] * dims_[2]), rank / dims_[2] % dims_[1], rank % dims_[2]};
  Block b;
  for (int a = 0; a < 3; ++a) {
    const Block along = split_axis(cells_[a], dims_[a], coords[a]);
    b.begin[a] = along.begin[0];
    b.count[a] = along.count[0];
  }
  return b;
}

}  // namespace shockfield::parallel
