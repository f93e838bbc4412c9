// DBM benchmark: lattice-node updates per second of the compressible BGK model (D2V16, NND, RK3)
// on 1 and 2 threads, beside this machine's memory bandwidth measured here with a STREAM-style
// triad, converted to the node-update rate that bandwidth would allow for the bytes one step
// moves. Usage: dbm_bench [n (lattice n×n, default 512)] [steps (default 10)] [threads... (default
// 1 2)].
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "shockfield/dbm/simulation.hpp"

using namespace shockfield::dbm;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Best of 5 triads a = b + s·c over 3 arrays of 32 Mi doubles (768 MiB moved per pass).
double triad_bandwidth() {
  const std::size_t n = std::size_t{1} << 25;
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  double best = 0.0;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + 0.5 * c[i];
    best = std::max(best, 3.0 * 8.0 * n / seconds_since(t0));
  }
  return best + 0.0 * a[n / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 512;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice lattice;
  lattice.nx = lattice.ny = n;
  lattice.dx = lattice.dy = 1.0 / n;
  BgkSettings settings;
  settings.dt = 0.4 * lattice.dx / model.max_speed();
  settings.tau = settings.dt;
  // Bytes per node and step: each Runge–Kutta stage reads its input and writes its output row by
  // row (L(f) never goes to memory); stages 2 and 3 also read f^n: (2 + 3 + 3) × 16 doubles.
  const double bytes_per_node_step = (2 + 3 + 3) * 16 * 8.0;
  std::printf("DBM BGK D2V16, %d x %d lattice, %d steps, %.0f B moved per node-step\n", n, n, steps,
              bytes_per_node_step);
  std::printf(
      "| threads | node-updates/s | per velocity | triad bandwidth | bandwidth limit | "
      "fraction |\n|---|---|---|---|---|---|\n");
  std::vector<int> thread_counts;
  for (int a = 3; a < argc; ++a) thread_counts.push_back(std::atoi(argv[a]));
  if (thread_counts.empty()) thread_counts = {1, 2};
  double rates[2] = {0.0, 0.0};
  for (int threads : thread_counts) {
    omp_set_num_threads(threads);
    Simulation sim(model, lattice, Boundaries{}, settings);
    sim.initialize([](double x, double y) {
      return Macro{1.0 + 0.1 * x * y, 0.1 * y, -0.1 * x, 1.0 + 0.05 * x};
    });
    sim.step();  // warm-up
    const auto t0 = Clock::now();
    for (int s = 0; s < steps; ++s) sim.step();
    const double rate = static_cast<double>(n) * n * steps / seconds_since(t0);
    const double bandwidth = triad_bandwidth();
    const double limit = bandwidth / bytes_per_node_step;
    if (threads <= 2) rates[threads - 1] = rate;
    std::printf("| %d | %.3g | %.3g | %.2f GB/s | %.3g | %.0f%% |\n", threads, rate, rate * 16,
                bandwidth / 1e9, limit, 100 * rate / limit);
  }

  if (rates[0] > 0 && rates[1] > 0)
    std::printf("speed-up 2 threads / 1 thread: %.2f\n", rates[1] / rates[0]);
  return 0;
}
