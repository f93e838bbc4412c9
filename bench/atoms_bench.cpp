// Per-atom structure analysis (analysis/atoms): coordination + conventional CNA + centro-symmetry
// on ~10⁶ Cu atoms, against LAMMPS's coord/atom + cna/atom + centro/atom on the same atoms in the
// same run. Work: 63³ fcc cells (1,000,188 atoms, a = 3.615 Å) with Gaussian displacements of
// σ = 0.085 Å per component (the harmonic 300 K amplitude of Cu), periodic; cutoff 3.0858 Å
// (0.854 a), CSP with 12 neighbours. Ours: analyze_structure (neighbour table + the three
// analyses) on 1 and 2 OpenMP threads. LAMMPS (serial `lmp`): wall time of `read_data` + `eam` +
// `run 0` with the three computes reduced in the thermo output, minus the same run without them
// (so reading, the pair's neighbour list and forces cancel); peak RSS from /usr/bin/time.
//
//   OMP_WAIT_POLICY=passive build/release/bench/atoms_bench [--cells 63] [--repeats 3] [--no-lammps]
//   build/release/bench/atoms_bench --cells 63 --write-data FILE   (the same atoms as a data file, then exit)
//   build/release/bench/atoms_bench --cells 136 --write-dump FILE  (as a LAMMPS text dump, id type x y z, then exit)
// bench/atoms_compare.sh alternates this benchmark with LAMMPS run by run (medians, load averages).
#include <omp.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/lattice.hpp"

namespace aa = shockfield::analysis::atoms;
using shockfield::Vec3;

namespace {

constexpr double kCutoff = 3.0858;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct LammpsRun {
  double seconds = -1;
  double cpu = -1;  ///< user + system
  double peak_mb = -1;
  long long fcc = -1;
};

// One `lmp` run: wall seconds and peak RSS from /usr/bin/time, the fcc count from the log.
LammpsRun run_lammps(const std::string& data, bool computes) {
  const std::string input = "/tmp/atoms_bench.in", log = "/tmp/atoms_bench.log", timing = "/tmp/atoms_bench.time";
  std::ofstream in(input);
  in << "units metal\natom_style atomic\nboundary p p p\nread_data " << data << "\n"
     << "pair_style eam\npair_coeff * * Cu_u3.eam\n";
  if (computes)
    in << "compute cna all cna/atom " << kCutoff << "\ncompute csp all centro/atom fcc\n"
       << "compute coord all coord/atom cutoff " << kCutoff << "\n"
       << "variable isfcc atom c_cna==1\ncompute nfcc all reduce sum v_isfcc\n"
       << "compute sumcsp all reduce sum c_csp\ncompute sumcoord all reduce sum c_coord\n"
       << "thermo_style custom step c_nfcc c_sumcsp c_sumcoord\nthermo_modify format float %.0f\n";
  in << "run 0\n";
  in.close();
  const std::string cmd = "LAMMPS_POTENTIALS=/usr/share/lammps/potentials OMP_NUM_THREADS=1 /usr/bin/time -f '%e %U %S %M' -o " +
                          timing + " lmp -nocite -screen none -log " + log + " -in " + input + " > /dev/null 2>&1";
  LammpsRun r;
  if (std::system(cmd.c_str()) != 0) return r;
  std::ifstream t(timing);
  double kb = 0, user = 0, sys = 0;
  t >> r.seconds >> user >> sys >> kb;
  r.cpu = user + sys;
  r.peak_mb = kb / 1024.0;
  if (computes) {
    std::ifstream l(log);
    std::string line;
    bool next = false;
    while (std::getline(l, line)) {
      if (next) {
        long long step = 0;
        double nfcc = 0;
        if (std::sscanf(line.c_str(), "%lld %lf", &step, &nfcc) == 2) r.fcc = static_cast<long long>(nfcc);
        break;
      }
      next = line.find("Step") != std::string::npos && line.find("c_nfcc") != std::string::npos;
    }
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  int cells = 63, repeats = 3;
  bool lammps = true;
  std::string write_data_file, write_dump_file;
  bool phases = false;  // time the neighbour table and each analysis apart (where the 2-thread time goes)
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--cells") && k + 1 < argc) cells = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--repeats") && k + 1 < argc) repeats = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--no-lammps")) lammps = false;
    else if (!std::strcmp(argv[k], "--write-data") && k + 1 < argc) write_data_file = argv[++k];
    else if (!std::strcmp(argv[k], "--write-dump") && k + 1 < argc) write_dump_file = argv[++k];
    else if (!std::strcmp(argv[k], "--phases")) phases = true;
  }
  shockfield::md::LatticeSpec spec;
  spec.a0 = 3.615;
  const shockfield::md::Lattice lattice(spec);
  using shockfield::geometry::Boundary;
  const auto box = lattice.box({cells, cells, cells}, {Boundary::periodic, Boundary::periodic, Boundary::periodic});
  shockfield::md::Atoms atoms;
  atoms.mass = {63.546};
  atoms.type_names = {"Cu"};
  lattice.create_atoms(box, atoms);
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    for (int d = 0; d < 3; ++d) atoms.x[i][d] += 0.085 * shockfield::rng::normal(2026, i, static_cast<std::uint64_t>(d));
  if (!write_data_file.empty()) {
    shockfield::io::write_data(write_data_file, box, atoms, {"atoms_bench", false, false});
    std::printf("wrote %zu atoms to %s\n", atoms.nlocal, write_data_file.c_str());
    return 0;
  }
  if (!write_dump_file.empty()) {
    std::FILE* f = std::fopen(write_dump_file.c_str(), "w");
    if (!f) return 1;
    std::fprintf(f, "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%zu\nITEM: BOX BOUNDS pp pp pp\n", atoms.nlocal);
    for (int d = 0; d < 3; ++d) std::fprintf(f, "%.10g %.10g\n", box.lo[d], box.hi[d]);
    std::fprintf(f, "ITEM: ATOMS id type x y z\n");
    for (std::size_t i = 0; i < atoms.nlocal; ++i)
      std::fprintf(f, "%lld 1 %.6f %.6f %.6f\n", static_cast<long long>(atoms.id[i]), atoms.x[i][0], atoms.x[i][1], atoms.x[i][2]);
    std::fclose(f);
    std::printf("wrote %zu atoms to %s\n", atoms.nlocal, write_dump_file.c_str());
    return 0;
  }
  aa::AtomFrame frame;
  frame.box = box;
  frame.positions.assign(atoms.x.begin(), atoms.x.end());
  frame.ids = atoms.id;
  const double n = static_cast<double>(frame.size());
  std::printf("atoms %zu (%d^3 fcc cells, sigma 0.085 A), cutoff %.4f A, CSP N = 12\n", frame.size(), cells, kCutoff);

  aa::StructureAnalyses analyses;
  analyses.coordination = aa::Coordination{kCutoff};
  analyses.cna = aa::ConventionalCna{kCutoff};
  analyses.centro_symmetry = aa::CentroSymmetry{12};
  if (phases) {
    // Wall and CPU time of each phase on 1 and 2 threads, alternated, `repeats` times; medians.
    const char* names[] = {"neighbour table", "coordination", "CNA", "CSP"};
    std::vector<double> wall[2][4], cpu[2][4];
    for (int r = 0; r < repeats; ++r)
      for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        auto t0 = std::chrono::steady_clock::now();
        double c0 = cpu_seconds();
        auto lap = [&](int k) {
          wall[threads - 1][k].push_back(seconds_since(t0));
          cpu[threads - 1][k].push_back(cpu_seconds() - c0);
          t0 = std::chrono::steady_clock::now();
          c0 = cpu_seconds();
        };
        const aa::NeighborTable table(frame, analyses.request());
        lap(0);
        (void)analyses.coordination->compute(frame, table);
        lap(1);
        (void)analyses.cna->compute(frame, table);
        lap(2);
        (void)analyses.centro_symmetry->compute(frame, table);
        lap(3);
      }
    for (int k = 0; k < 4; ++k)
      std::printf("phase %-16s 1 thread wall %.3f s CPU %.3f s | 2 threads wall %.3f s CPU %.3f s | speed-up %.2f\n", names[k],
                  median(wall[0][k]), median(cpu[0][k]), median(wall[1][k]), median(cpu[1][k]),
                  median(wall[0][k]) / median(wall[1][k]));
    return 0;
  }
  std::size_t our_fcc = 0, table_bytes = 0;
  double best1 = 0, cpu1 = 0;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::vector<double> times, cpu;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = cpu_seconds();
      const auto result = aa::analyze_structure(frame, analyses);
      times.push_back(seconds_since(t0));
      cpu.push_back(cpu_seconds() - c0);
      our_fcc = result.cna->counts.of(aa::Structure::fcc);
      table_bytes = result.neighbor_table_bytes;
    }
    const double med = median(times), best = *std::min_element(times.begin(), times.end());
    if (threads == 1) best1 = med, cpu1 = median(cpu);
    std::printf("shockfield %d thread(s): wall median %.3f s (min %.3f) = %.3g atoms/s, CPU median %.3f s%s\n", threads,
                med, best, n / med, median(cpu), threads == 2 ? (", wall speed-up " + std::to_string(best1 / med)).c_str() : "");
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("shockfield: fcc %zu; neighbour table %.1f bytes/atom; peak RSS %.1f MB (frame, lattice and table)\n",
              our_fcc, static_cast<double>(table_bytes) / n, static_cast<double>(usage.ru_maxrss) / 1024.0);
  if (!lammps) return 0;
  const std::string data = "/tmp/atoms_bench.data";
  shockfield::io::write_data(data, box, atoms, {"atoms_bench", false, false});
  std::vector<double> with, without, with_cpu, without_cpu;
  LammpsRun last_with, last_without;
  for (int r = 0; r < std::max(repeats - 1, 1); ++r) {
    last_without = run_lammps(data, false);
    last_with = run_lammps(data, true);
    with.push_back(last_with.seconds);
    without.push_back(last_without.seconds);
    with_cpu.push_back(last_with.cpu);
    without_cpu.push_back(last_without.cpu);
  }
  std::remove(data.c_str());
  if (last_with.seconds < 0 || last_without.seconds < 0) {
    std::printf("LAMMPS: lmp failed (see /tmp/atoms_bench.log)\n");
    return 1;
  }
  const double computes = median(with) - median(without);
  std::printf("LAMMPS serial: run 0 with computes %.3f s, without %.3f s -> computes %.3f s = %.3g atoms/s; fcc %lld\n",
              median(with), median(without), computes, n / computes, last_with.fcc);
  std::printf("LAMMPS peak RSS: %.1f MB with computes, %.1f MB without (%.1f bytes/atom for the computes)\n",
              last_with.peak_mb, last_without.peak_mb, (last_with.peak_mb - last_without.peak_mb) * 1048576.0 / n);
  const double computes_cpu = median(with_cpu) - median(without_cpu);
  std::printf("LAMMPS computes CPU (user+sys difference): %.3f s = %.3g atoms/s\n", computes_cpu, n / computes_cpu);
  std::printf("ratio LAMMPS / shockfield 1 thread: wall %.2f, CPU %.2f\n", computes / best1, computes_cpu / cpu1);
  return 0;
}
