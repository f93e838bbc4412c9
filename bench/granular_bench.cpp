// Granular chain benchmark and example data.
//   granular_bench [grains (default 1000000)] [steps (default 300)]
//     grain-steps per second (grains × steps / loop time) of a steel column of `grains` spheres
//     under gravity hit on top at 1 m/s, on 1 and 2 threads (every contact is loaded, so the
//     branch-free loop does the same work wherever the signal is).
//   granular_bench --examples DIR
//     writes the CSV files that examples/granular_chain/plot.py draws: the space–time force map
//     of a solitary-wave train, the signal against depth in a column (weak and strong impulse),
//     and the energy backscattered above a light and a heavy impurity against time.
#include <omp.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "shockfield/granular/outputs.hpp"
#include "shockfield/granular/signal.hpp"
#include "shockfield/granular/simulation.hpp"
#include "shockfield/io/csv_writer.hpp"

using namespace shockfield;
using namespace shockfield::granular;
using Clock = std::chrono::steady_clock;

namespace {

// Steel spheres of R = 2 mm on a rigid floor under gravity.
ChainSpec steel_column(long long n) {
  return {.grains = n, .radius = 2e-3, .gravity = 9.81, .wall = WallKind::rigid, .impurities = {}};
}

struct Rate {
  double wall = 0.0;  ///< grain-steps per second of wall time
  double cpu = 0.0;   ///< grain-steps per second of the process's CPU time (all threads)
};

// On a shared machine the wall-time rate depends on the load; the CPU-time rate does much less.
Rate grain_steps_per_second(long long grains, int steps, int threads) {
  omp_set_num_threads(threads);
  Simulation sim(build_chain(steel_column(grains)), Impulse{Impulse::Kind::velocity, 1.0, 1, {}, {}});
  sim.step();  // first touch of every array
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  for (int s = 0; s < steps; ++s) sim.step();
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double work = static_cast<double>(grains) * steps;
  return {work / seconds, work / cpu};
}

// A 5-grain impulse on a free horizontal chain of 300: the space–time fields of force and velocity.
void write_train(const std::filesystem::path& dir) {
  ChainSpec s;
  s.grains = 300;
  s.radius = 5e-3;
  const Impulse kick{Impulse::Kind::velocity, 0.5, 5, {}, {}};
  Simulation sim(build_chain(s), kick, std::nullopt, 0.02);
  GranularCase train;
  train.chain = s;
  OutputSpec& out = train.output;
  out.schedule.series_interval = 1e-5;
  out.schedule.field_interval = 2e-5;
  out.probes = {50, 150, 250};
  out.probe_interval = 1e-6;
  const auto folder = dir / "train";
  std::filesystem::create_directories(folder);
  RunOutputs outputs(folder, train, sim, 0);
  OutputCounters counters;
  while (sim.time() < 4e-3) {  // the front (~670 m/s) reaches the far end at ~4.5 ms
    sim.step();
    outputs.write_due(sim, counters);
  }
}

// The leading peak of a column of 3000 grains hit at v0, measured 200 times.
void write_column(const std::filesystem::path& dir, const std::string& name, double v0, double t_end) {
  Simulation sim(build_chain(steel_column(3000)), Impulse{Impulse::Kind::velocity, v0, 1, {}, {}},
                 std::nullopt, 0.1);
  const std::vector<SignalSample> samples = track_signal(sim, t_end);
  io::CsvWriter csv(dir / (name + ".csv"), {"time", "position", "depth", "speed", "velocity", "force", "width"});
  for (const SignalSample& x : samples) csv.row({x.time, x.position, x.depth, x.speed, x.velocity, x.force, x.width});
}

// Light (m/10) and heavy (10 m) impurity at grain 200 of an 800-grain column hit at 1 m/s.
void write_backscatter(const std::filesystem::path& dir) {
  const Impulse kick{Impulse::Kind::velocity, 1.0, 1, {}, {}};
  ChainSpec s = steel_column(800);
  Simulation reference(build_chain(s), kick, std::nullopt, 0.05);
  s.impurities = {{200, 0.1, 1, 1, {}}};
  Simulation light(build_chain(s), kick, reference.time_step());
  s.impurities = {{200, 10.0, 1, 1, {}}};
  Simulation heavy(build_chain(s), kick, reference.time_step());
  const double e0 = reference.thermo().total;
  io::CsvWriter csv(dir / "backscatter.csv", {"time", "light_reflected", "heavy_reflected", "light_impurity_kinetic",
                                              "heavy_impurity_kinetic"});
  const auto every = static_cast<long long>(2.5e-3 / 1000 / reference.time_step());
  while (reference.time() < 2.5e-3) {
    reference.step();
    light.step();
    heavy.step();
    if (reference.step_count() % every == 0) {
      const auto kinetic = [](const Simulation& sim) {
        return 0.5 * sim.chain().mass[200] * sim.velocity()[200] * sim.velocity()[200];
      };
      csv.row({reference.time(), reflected_energy(light, reference, 200) / e0,
               reflected_energy(heavy, reference, 200) / e0, kinetic(light) / e0, kinetic(heavy) / e0});
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--examples") {
    const std::filesystem::path dir = argv[2];
    std::filesystem::create_directories(dir);
    omp_set_num_threads(1);
    write_train(dir);
    write_column(dir, "column_weak", 1e-4, 0.02);
    write_column(dir, "column_strong", 1.0, 0.012);
    write_backscatter(dir);
    std::printf("wrote %s\n", dir.c_str());
    return 0;
  }
  const long long grains = argc > 1 ? std::atoll(argv[1]) : 1000000;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 300;
  for (int threads : {1, 2}) {
    const Rate r = grain_steps_per_second(grains, steps, threads);
    std::printf("granular chain: %lld grains, %d steps, %d thread(s): %.3g grain-steps/s (wall), %.3g per CPU-second\n",
                grains, steps, threads, r.wall, r.cpu);
  }
  return 0;
}
