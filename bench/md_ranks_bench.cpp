// MD on MPI ranks (docs/parallel.md, bench/RESULTS.md "## MD on MPI ranks"): the work of LAMMPS's
// bench/lammps/in.eam — fcc Cu (a = 3.615 Å), n³ unit cells (n = 20: 32,000 atoms), Cu_u3.eam,
// 1600 K, NVE, Δt = 0.005 ps, skin 1 Å, neigh_modify every 1 delay 5 check yes — on the rank grid
// with the least halo, timed over `steps` steps after setup. Prints the loop time, the atom-step
// rate and, the largest over ranks, the time in the particle exchange (ghost positions, EAM
// densities and forces across ranks, migration and ghost rebuilds) per step. Run as
//   mpirun -np P md_ranks_bench [n (20)] [steps (100)]     (OMP_NUM_THREADS=1 per rank)
// and compare with `mpirun -np P lmp -in bench/lammps/in.eam` (bench/md_ranks_compare.sh).
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "shockfield/core/config.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/lattice.hpp"
#include "shockfield/md/potentials/registry.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/velocity.hpp"

using namespace shockfield;
using namespace shockfield::md;

int main(int argc, char** argv) {
  const parallel::Environment mpi(argc, argv);
  const parallel::Communicator world = parallel::Communicator::world();
  const int n = argc > 1 ? std::atoi(argv[1]) : 20, steps = argc > 2 ? std::atoi(argv[2]) : 100;
  LatticeSpec spec;
  spec.a0 = 3.615;
  const Lattice lattice(spec);
  const geometry::Box box = lattice.box({n, n, n}, {geometry::Boundary::periodic, geometry::Boundary::periodic,
                                                    geometry::Boundary::periodic});
  Atoms atoms;
  atoms.mass = {0};
  atoms.type_names = {"Cu"};
  lattice.create_atoms(box, atoms);
  const Config config = Config::parse("style = \"eam\"\nfile = \"Cu_u3.eam\"\n", "bench.toml");
  auto potential = potentials::make_potential(config, ".", 1);
  atoms.mass = {63.55};
  create_velocities(atoms, 1600.0, 376847);
  const double range = potential->cutoff() + 1.0;
  const auto domain = std::make_shared<Decomposition>(world, md_rank_grid(box, range, world.size(), {0, 0, 0}), box, range);
  keep_own_atoms(*domain, atoms);
  Simulation sim(box, std::move(atoms), std::move(potential), 0.005, 1.0);
  sim.domain = domain;
  sim.neighbor_delay = 5;
  sim.fixes.push_back(std::make_unique<FixNve>());
  sim.setup(false);
  domain->halo_seconds = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) sim.advance([](std::int64_t) { return false; });
  const double loop = domain->max(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const double halo = domain->max(domain->halo_seconds);
  const ThermoState t = sim.thermo();
  const long long total = domain->total_atoms(sim.atoms);
  if (world.is_root())
    std::printf("%d ranks: %lld atoms, %d steps: loop %.3f s, %.3g atom-steps/s, exchange %.3f ms/step (largest "
                "rank), %lld rebuilds; final T %.2f K, pe %.6f eV\n",
                world.size(), total, steps, loop, static_cast<double>(total) * steps / loop, 1e3 * halo / steps,
                static_cast<long long>(sim.rebuilds), t.temperature, t.potential);
  return 0;
}
