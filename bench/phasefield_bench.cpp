// Phase-field step cost against its physical floor (docs/phasefield.md; bench/RESULTS.md).
//   phasefield_bench [nodes per axis (default 256)] [steps (default 10)]
//     node-updates per second of the 3D semi-implicit spectral scheme and of the explicit scheme
//     on n³ nodes, on 1 and 2 threads, beside the time of one FFTW r2c plus one c2r transform of the
//     same grid with the solver's plan flags (FFTW_ESTIMATE, single-threaded): a spectral step is
//     those two transforms plus pointwise work, so "step / two transforms" is its overhead
//     (goal 1.5). Medians of three repetitions.
#include <fftw3.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "shockfield/phasefield/initial.hpp"
#include "shockfield/phasefield/solver.hpp"

using namespace shockfield::phasefield;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class Work>
double seconds_per_call(int calls, Work&& work) {
  const auto start = Clock::now();
  for (int s = 0; s < calls; ++s) work();
  return std::chrono::duration<double>(Clock::now() - start).count() / calls;
}

// One r2c and one c2r transform of the grid with the solver's flags.
struct TwoTransforms {
  std::vector<double> real;
  std::vector<std::complex<double>> spectrum;
  fftw_plan forward, backward;
  explicit TwoTransforms(const Grid& g)
      : real(g.size(), 0.25), spectrum(static_cast<std::size_t>(g.n[0] / 2 + 1) * g.n[1] * g.n[2]) {
    auto* c = reinterpret_cast<fftw_complex*>(spectrum.data());
    const int dims[3] = {g.n[2], g.n[1], g.n[0]};
    forward = fftw_plan_dft_r2c(3, dims, real.data(), c, FFTW_ESTIMATE | FFTW_UNALIGNED);
    backward = fftw_plan_dft_c2r(3, dims, c, real.data(), FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_DESTROY_INPUT);
  }
  ~TwoTransforms() {
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
  void operator()() {
    fftw_execute(forward);
    fftw_execute(backward);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 256;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
  if (n < 8 || steps < 1) {
    std::fprintf(stderr, "usage: phasefield_bench [nodes per axis >= 8] [steps >= 1]\n");
    return 2;
  }
  const Grid g{3, {n, n, n}, 0.5};
  const Model model{0.3, 1.0};
  const double nodes = static_cast<double>(g.size());
  TwoTransforms fft(g);
  Solver spectral(g, model, Scheme::spectral, 0.1);
  Solver explicit_euler(g, model, Scheme::explicit_euler, 0.5 * explicit_step_limit(g, model));
  spectral.field() = explicit_euler.field() = initial_field(g, model, random_domains(g, {40, 4.0, 1}));
  fft(), spectral.step(), explicit_euler.step();  // first touch
  // Alternated: every repetition times each configuration in turn (the host's load drifts).
  std::vector<double> t_fft, t_spectral[2], t_explicit[2];
  for (int r = 0; r < 3; ++r) {
    t_fft.push_back(seconds_per_call(steps, fft));
    for (int threads = 1; threads <= 2; ++threads) {
      omp_set_num_threads(threads);
      t_spectral[threads - 1].push_back(seconds_per_call(steps, [&] { spectral.step(); }));
      t_explicit[threads - 1].push_back(seconds_per_call(steps, [&] { explicit_euler.step(); }));
    }
  }
  const double two = median(t_fft);
  std::printf("grid %d^3 (%.3g nodes), %d steps per repetition, medians of 3 alternated repetitions\n", n, nodes, steps);
  std::printf("two FFTW transforms (r2c + c2r, single-threaded as in the solver): %.4f s\n", two);
  for (int threads = 1; threads <= 2; ++threads) {
    const double s = median(t_spectral[threads - 1]), e = median(t_explicit[threads - 1]);
    std::printf("spectral %d thread(s): %.4f s/step, %.3g node-updates/s, step / two transforms %.2f\n", threads, s,
                nodes / s, s / two);
    std::printf("explicit %d thread(s): %.4f s/step, %.3g node-updates/s\n", threads, e, nodes / e);
  }
  return 0;
}
