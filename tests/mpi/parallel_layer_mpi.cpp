// The decomposition layer on however many ranks mpirun starts (ctest label mpi: 1, 2 and 4 ranks).
// A 13 x 7 grid, periodic in x and not in y, 2 components, 2 ghost layers, holds in each cell its
// global id; after the x and y halo exchanges every ghost with a neighbour (corners included)
// must hold the id of the cell it images, the ghosts at the y edges must be untouched; a gather of
// the blocks must give the whole grid and a scatter back the blocks; an ordered sum of per-row
// values must have the bits of the one-rank sum. Exit 0 when every rank passes.
#include <cmath>
#include <cstdio>
#include <string>

#include "shockfield/parallel/block_transfer.hpp"
#include "shockfield/parallel/halo_exchange.hpp"
#include "shockfield/parallel/ordered_sum.hpp"
#include "shockfield/parallel/rank_grid.hpp"

using namespace shockfield::parallel;

namespace {

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok && failures++ < 10) std::fprintf(stderr, "rank %d: %s\n", Communicator::world().rank(), what.c_str());
}

constexpr int nx = 13, ny = 7, w = 2, components = 2;
double id(int c, long long i, long long j) { return 1000.0 * c + 20.0 * j + static_cast<double>(i); }

GridLayout layout(long long bx, long long by) {
  GridLayout l{{static_cast<int>(bx), static_cast<int>(by), 1}, {w, w, 0}, components, 0};
  l.component_stride = l.cells();
  return l;
}

}  // namespace

int main(int argc, char** argv) {
  const Environment mpi(argc, argv);
  const Communicator world = Communicator::world();
  const Cells3 cells{nx, ny, 1};
  // The rank grid chosen for the rank count, or given as "PxQ" (2x2: corners across both cuts).
  Dims3 dims = choose_rank_grid(cells, world.size(), w);
  if (argc > 1 && std::sscanf(argv[1], "%dx%d", &dims[0], &dims[1]) == 2) dims[2] = 1;
  const RankGrid grid(world, dims, {true, false, false}, cells, w);
  const Block& b = grid.block();
  const GridLayout l = layout(b.count[0], b.count[1]);
  std::vector<double> f(components * l.cells(), -1.0);
  for (int c = 0; c < components; ++c)
    for (int j = 0; j < b.count[1]; ++j)
      for (int i = 0; i < b.count[0]; ++i) f[c * l.component_stride + l.at(i, j, 0)] = id(c, b.begin[0] + i, b.begin[1] + j);

  const HaloExchange halo(grid.comm(), l);
  halo.exchange(f.data(), 0);
  halo.exchange(f.data(), 1);
  for (int c = 0; c < components; ++c)
    for (int j = -w; j < b.count[1] + w; ++j)
      for (int i = -w; i < b.count[0] + w; ++i) {
        const long long gi = ((b.begin[0] + i) % nx + nx) % nx, gj = b.begin[1] + j;
        const double got = f[c * l.component_stride + l.at(i, j, 0)];
        const std::string where = "cell (" + std::to_string(i) + ", " + std::to_string(j) + ") component " + std::to_string(c);
        if (gj < 0 || gj >= ny) check(got == -1.0, where + ": a y-edge ghost was written");
        else check(got == id(c, gi, gj), where + ": holds " + std::to_string(got) + ", expected " + std::to_string(id(c, gi, gj)));
      }

  const GridLayout whole = layout(nx, ny);
  std::vector<double> all(components * whole.cells(), -1.0), back(f.size(), -2.0);
  gather_blocks(grid, l, f.data(), whole, all.data());
  if (world.is_root())
    for (int c = 0; c < components; ++c)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) check(all[c * whole.component_stride + whole.at(i, j, 0)] == id(c, i, j), "gather");
  scatter_blocks(grid, whole, all.data(), l, back.data());
  for (int c = 0; c < components; ++c)
    for (int j = 0; j < b.count[1]; ++j)
      for (int i = 0; i < b.count[0]; ++i)
        check(back[c * l.component_stride + l.at(i, j, 0)] == f[c * l.component_stride + l.at(i, j, 0)], "scatter");

  // Per-row partial sums of values spanning 12 decades, reduced in row order.
  auto value = [](long long g) { return std::pow(10.0, static_cast<double>(g % 13) - 6.0) / (3.0 + g); };
  std::vector<double> rows;
  std::vector<long long> index;
  for (long long j = 0; j < b.count[1]; ++j)
    for (long long i = 0; i < b.count[0]; ++i) {
      rows.push_back(value((b.begin[1] + j) * nx + b.begin[0] + i));
      index.push_back((b.begin[1] + j) * nx + b.begin[0] + i);
    }
  double serial = 0.0;
  for (long long g = 0; g < nx * ny; ++g) serial += value(g);
  check(ordered_sum(world, rows, index, 1)[0] == serial, "ordered sum differs from the one-rank sum");

  const bool all_passed = world.min(failures == 0 ? 1 : 0) == 1;
  if (world.is_root())
    std::printf("parallel layer on %d ranks (rank grid %d x %d x %d): %s\n", world.size(), grid.dims()[0],
                grid.dims()[1], grid.dims()[2], all_passed ? "passed" : "FAILED");
  return all_passed ? 0 : 1;
}
