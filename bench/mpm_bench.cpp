// MPM throughput: particle-steps per second of the solver loop (MUSL, GIMP, seed aluminium) for
// the seed's 2D porous case at full width (2 mm × 5 mm, Δ = 0.029, r = 50 µm, 5 µm cells,
// 1.55·10⁶ particles, wall impact at 1000 m/s) and a 3D block with a cavity (10⁶ particles), on 1
// and 2 threads, and the resident memory per particle. Plain executable:
//   build/mpm/bench/mpm_bench [steps] [2d|3d|3d10m|all] [1|2|both]
// (the case and thread-count selectors let `perf stat` count the cycles of one configuration;
// steps = 0 measures the set-up alone, to be subtracted).
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "shockfield/materials/library.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace {

using namespace shockfield;

double rss_bytes() {
  std::ifstream in("/proc/self/status");
  std::string key;
  double kb = 0;
  while (in >> key)
    if (key == "VmRSS:") in >> kb;
  return kb * 1024.0;
}

void measure(const char* name, int dim, const mpm::Body& body, const std::vector<mpm::Void>& voids, const mpm::GridSpec& grid,
             int steps, const std::vector<int>& thread_counts) {
  const auto al = materials::aluminium_seed000();
  const double before = rss_bytes();
  mpm::Particles p;
  mpm::add_body(p, dim, body, al, voids);
  mpm::SimulationOptions opt;
  opt.shape = mpm::ShapeKind::Gimp;
  mpm::Simulation sim(grid, {al}, std::move(p), opt);
  sim.step();  // sizes every work array
  const double per_particle = (rss_bytes() - before) / static_cast<double>(sim.particles().size());
  for (int threads : thread_counts) {
    omp_set_num_threads(threads);
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) sim.step();
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-34s %2d thread(s): %9zu particles, %3d steps, %.3g particle-steps/s, %.0f B/particle\n", name, threads,
                sim.particles().size(), steps, static_cast<double>(sim.particles().size()) * steps / secs, per_particle);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 10;
  const std::string which = argc > 2 ? argv[2] : "all", threads = argc > 3 ? argv[3] : "both";
  const std::vector<int> counts = threads == "both" ? std::vector<int>{1, 2} : std::vector<int>{std::atoi(threads.c_str())};
  if (which == "all" || which == "2d") {
    const double h = 5e-6;
    const mpm::Body body{Vec3(0, 0, 0), Vec3(2e-3, 5e-3, 0), h / 2, Vec3(0, -1000.0, 0), 0};
    const auto voids = mpm::place_voids(2, body, {0.029, 50e-6, 0.0, 2024});
    measure("2D porous Al (seed Fig 19 set-up)", 2, body, voids,
            mpm::impact_grid(2, Vec3::Zero(), Vec3(2e-3, 5.2e-3, 0), h, mpm::Wall::Slip), steps, counts);
  }
  // "3d" is the 10⁶-point block; "3d10m" the same set-up 216 µm wide, 1.0·10⁷ points (issue 3:
  // must fit in 24 GiB; not part of "all").
  for (const double side : {100e-6, 216e-6}) {
    if (!(side < 150e-6 ? which == "all" || which == "3d" : which == "3d10m")) continue;
    const double h = 2e-6;
    const mpm::Body body{Vec3(0, 0, 0), Vec3(side, side, side), h / 2, Vec3(0, 0, -1000.0), 0};
    measure("3D block with a cavity", 3, body, {mpm::cavity_at(3, body, side / 2, 10e-6)},
            mpm::impact_grid(3, Vec3::Zero(), Vec3(side, side, side + 10e-6), h, mpm::Wall::Slip), steps, counts);
  }
}
