// DBM on MPI ranks (docs/parallel.md, bench/RESULTS.md "## DBM on MPI ranks"): per rank, the time
// of one halo exchange of the BGK distributions (16 velocities, 2 ghost layers, both axes) and of
// one RK3 step of its block (3 exchanges included), medians over `steps` steps, on an n × n
// periodic lattice cut by the rank grid with the least halo. Run as
//   mpirun -np P dbm_halo_bench [n (512)] [steps (20)]
// and compare the step time of -np 1 and -np 2 (OMP_NUM_THREADS=1 per rank).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "shockfield/dbm/simulation.hpp"
#include "shockfield/parallel/halo_exchange.hpp"
#include "shockfield/parallel/rank_grid.hpp"

using namespace shockfield;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const parallel::Environment mpi(argc, argv);
  const int n = argc > 1 ? std::atoi(argv[1]) : 512, steps = argc > 2 ? std::atoi(argv[2]) : 20;
  const parallel::Communicator world = parallel::Communicator::world();
  const parallel::Cells3 cells{n, n, 1};
  const parallel::RankGrid grid(world, parallel::choose_rank_grid(cells, world.size(), dbm::Lattice::ghosts),
                                {true, true, false}, cells, dbm::Lattice::ghosts);
  dbm::Lattice lattice;
  lattice.nx = static_cast<int>(grid.block().count[0]);
  lattice.ny = static_cast<int>(grid.block().count[1]);
  lattice.dx = lattice.dy = 1.0 / n;
  const dbm::VelocityModel model = dbm::d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  dbm::Boundaries periodic;  // periodic on every side (the default)
  dbm::BgkSettings bgk;
  bgk.dt = 0.2 / n / model.max_speed(), bgk.tau = bgk.dt;  // tau = dt, as examples/dbm_sod
  dbm::Simulation sim(model, lattice, periodic, bgk);
  const parallel::GridLayout layout{{lattice.nx, lattice.ny, 1}, {2, 2, 0}, model.size(), lattice.cells()};
  const parallel::Dims3& dims = grid.dims();
  const parallel::HaloExchange halo(grid.comm(), layout, {dims[0] > 1, dims[1] > 1, false});
  sim.set_halo(&halo);
  const double x0 = static_cast<double>(grid.block().begin[0]) / n;
  sim.initialize([&](double x, double y) {
    return dbm::Macro{1.0 + 0.1 * std::sin(2 * M_PI * (x + x0)), 0.1, 0.0, 1.0 + 0.05 * std::cos(2 * M_PI * y)};
  });

  std::vector<double> exchange_s, step_s;
  for (int s = 0; s <= steps; ++s) {
    grid.comm().min(0);  // line the ranks up
    auto t0 = Clock::now();
    halo.exchange(sim.f().data(), 0);
    halo.exchange(sim.f().data(), 1);
    const double exchange = std::chrono::duration<double>(Clock::now() - t0).count();
    grid.comm().min(0);
    t0 = Clock::now();
    sim.step();
    const double step = std::chrono::duration<double>(Clock::now() - t0).count();
    if (s > 0) exchange_s.push_back(exchange), step_s.push_back(step);  // step 0: warm-up
  }
  if (world.is_root()) {
    const double cells_per_rank = static_cast<double>(lattice.nx) * lattice.ny;
    std::printf("dbm_halo_bench %d x %d on %d ranks (rank grid %d x %d), block %d x %d, %d steps\n", n, n,
                world.size(), dims[0], dims[1], lattice.nx, lattice.ny, steps);
    std::printf("  halo doubles sent per exchange (both axes): %zu (%.1f KiB)\n", halo.doubles_per_exchange(),
                8.0 * halo.doubles_per_exchange() / 1024.0);
    std::printf("  rank 0 median halo exchange: %.3g ms; median step (3 exchanges): %.3g ms\n",
                1e3 * median(exchange_s), 1e3 * median(step_s));
    std::printf("  cell-updates/s per rank: %.3g; whole lattice: %.3g\n", cells_per_rank / median(step_s),
                static_cast<double>(n) * n / median(step_s));
  }
  return 0;
}
