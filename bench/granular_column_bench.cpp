// The 2D column of spheres (granular/column.hpp) for bench/granular_column_compare.sh:
//   granular_column_bench [per_row (1000)] [rows (1000)] [steps (100)]
// builds per_row × rows steel spheres (R = 1 mm) on a triangular lattice of spacing 2R(1 − 1e-4)
// (every neighbour pair overlaps by 2e-7 m, so every contact carries a force), the same spheres
// as bench/lammps/in.granular_column (lattice hex), in a box with walls 1 µm off the outer
// spheres and gravity, and times `steps` velocity-Verlet steps after one warm-up step on
// OMP_NUM_THREADS threads. Prints: spheres, steps, threads, loop seconds, sphere-steps per second.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "shockfield/granular/column.hpp"

using namespace shockfield;
using namespace shockfield::granular;

int main(int argc, char** argv) {
  const long long per_row = argc > 1 ? std::atoll(argv[1]) : 1000;
  const long long rows = argc > 2 ? std::atoll(argv[2]) : 1000;
  const int steps = argc > 3 ? std::atoi(argv[3]) : 100;
  const double R = 1e-3, a = 2 * R * (1 - 1e-4);
  md::Atoms atoms;
  std::int64_t id = 0;
  for (long long j = 0; j < rows; ++j)
    for (long long i = 0; i < per_row; ++i)
      atoms.add(Vec3((static_cast<double>(i) + 0.5 * static_cast<double>(j % 2)) * a,
                     static_cast<double>(j) * std::sqrt(3.0) / 2 * a, 0.0),
                0, ++id);
  ColumnSpec spec;
  spec.types = {SphereType{}};
  spec.left = -R - 1e-6;
  spec.right = (static_cast<double>(per_row) - 0.5) * a + R + 1e-6;
  spec.floor = -R - 1e-6;
  spec.time_step = 5e-8;
  Column column(spec, std::move(atoms));
  column.step();
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) column.step();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double work = static_cast<double>(per_row * rows) * steps;
  std::printf("spheres %lld steps %d threads %d loop_s %.4f sphere_steps_per_s %.4g list_builds %lld\n",
              per_row * rows, steps, omp_get_max_threads(), seconds, work / seconds, column.neighbor_builds());
  return 0;
}
