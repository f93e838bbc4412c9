#include "shockfield/parallel/block_transfer.hpp"

#include <vector>

namespace shockfield::parallel {
namespace {

// Visits the interior cells of `block` (components, then z, y, x) as storage indices of `layout`,
// offset by `origin` (the block's first cell in that layout's coordinates).
template <class Visit>
void for_each_cell(const GridLayout& layout, const Cells3& origin, const Cells3& count, Visit visit) {
  for (int c = 0; c < layout.components; ++c)
    for (long long k = 0; k < count[2]; ++k)
      for (long long j = 0; j < count[1]; ++j)
        for (long long i = 0; i < count[0]; ++i)
          visit(static_cast<std::size_t>(c) * layout.component_stride +
                layout.at(static_cast<int>(origin[0] + i), static_cast<int>(origin[1] + j),
                          static_cast<int>(origin[2] + k)));
}

std::size_t interior_values(const Block& b, int components) {
  return static_cast<std::size_t>(b.count[0] * b.count[1] * b.count[2]) * static_cast<std::size_t>(components);
}

}  // namespace

void gather_blocks(const RankGrid& grid, const GridLayout& local, const double* local_data, const GridLayout& global,
                   double* global_data) {
  const Block& mine = grid.block();
  std::vector<double> packed;
  packed.reserve(interior_values(mine, local.components));
  for_each_cell(local, {0, 0, 0}, mine.count, [&](std::size_t s) { packed.push_back(local_data[s]); });
  const std::vector<double> all = grid.comm().gather(packed);
  if (!grid.comm().is_root()) return;
  std::size_t n = 0;
  for (int r = 0; r < grid.comm().size(); ++r) {
    const Block b = grid.block_of(r);
    for_each_cell(global, b.begin, b.count, [&](std::size_t s) { global_data[s] = all[n++]; });
  }
}

void scatter_blocks(const RankGrid& grid, const GridLayout& global, const double* global_data,
                    const GridLayout& local, double* local_data) {
  std::vector<std::vector<double>> pieces;
  if (grid.comm().is_root()) {
    for (int r = 0; r < grid.comm().size(); ++r) {
      const Block b = grid.block_of(r);
      std::vector<double>& piece = pieces.emplace_back();
      for_each_cell(global, b.begin, b.count, [&](std::size_t s) { piece.push_back(global_data[s]); });
    }
  }
  const Block& mine = grid.block();
  const std::vector<double> piece = grid.comm().scatter(pieces, interior_values(mine, local.components));
  std::size_t n = 0;
  for_each_cell(local, {0, 0, 0}, mine.count, [&](std::size_t s) { local_data[s] = piece[n++]; });
}

}  // namespace shockfield::parallel
