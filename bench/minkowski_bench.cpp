// Minkowski functionals for every threshold in one pass (analysis/minkowski), against
// scikit-image doing the same one threshold at a time (bench/minkowski_skimage.py), same fields,
// same run. Cases: a 4096² Gaussian field with 256 thresholds (A, L, χ) and a 256³ field with 64
// thresholds (V, S, b̄, χ). Rate: cell-thresholds per second; ratio = skimage time / ours.
//
//   build/release/bench/minkowski_bench [--stride2d 8] [--stride3d 4] [--repeats 5]
// The skimage loop is timed on every stride-th threshold and scaled to all thresholds (stride 1:
// the whole loop). Run from the repository root (it calls bench/minkowski_skimage.py).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "shockfield/analysis/gaussian_random_field.hpp"
#include "shockfield/analysis/minkowski.hpp"

namespace sa = shockfield::analysis;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double skimage_seconds(const sa::GridField& f, double lo, double hi, int count, int stride) {
  const std::string path = "/tmp/shockfield_minkowski_bench.f64";
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(f.values.data()),
             static_cast<std::streamsize>(f.values.size() * sizeof(double)));
  const std::string cmd = "/usr/bin/python3 " SHOCKFIELD_SOURCE_DIR "/bench/minkowski_skimage.py " +
                          path + " " + std::to_string(f.n[0]) + " " + std::to_string(f.n[1]) +
                          " " + std::to_string(f.n[2]) + " " + std::to_string(lo) + " " +
                          std::to_string(hi) + " " + std::to_string(count) + " " +
                          std::to_string(stride);
  FILE* pipe = popen(cmd.c_str(), "r");
  double per = 0.0;
  int timed = 0;
  if (!pipe || std::fscanf(pipe, "%lf %d", &per, &timed) != 2) per = -1.0;
  if (pipe) pclose(pipe);
  std::remove(path.c_str());
  return per * count;
}

template <class Run>
void run_case(const char* name, const sa::GridField& f, int count, int stride, int repeats,
              Run run) {
  std::vector<double> thresholds;
  for (int k = 0; k < count; ++k) thresholds.push_back(-3.0 + 6.0 * k / (count - 1));
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    run(f, thresholds);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  const double ours = median(times);
  const double theirs = skimage_seconds(f, -3.0, 3.0, count, stride);
  const double rate = double(f.size()) * count / ours;
  std::printf("%-28s threads %d  ours median %.3f s (min %.3f, %d runs)  %.3g cell-thresholds/s  "
              "skimage %.1f s (%d of %d thresholds timed)  ratio %.1fx\n",
              name, omp_get_max_threads(), ours, *std::min_element(times.begin(), times.end()),
              repeats, rate, theirs, (count + stride - 1) / stride, count, theirs / ours);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int stride2d = 8, stride3d = 4, repeats = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--stride2d")) stride2d = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--stride3d")) stride3d = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--repeats")) repeats = std::atoi(argv[i + 1]);
  }
  const auto f2 = sa::gaussian_random_field(4096, 4096, 1, 8.0, 1).field;
  run_case("2D 4096^2, 256 thresholds", f2, 256, stride2d, repeats,
           [](const auto& f, const auto& t) { return sa::minkowski_2d(f, t); });
  const auto f3 = sa::gaussian_random_field(256, 256, 256, 4.0, 2).field;
  run_case("3D 256^3, 64 thresholds", f3, 64, stride3d, repeats,
           [](const auto& f, const auto& t) { return sa::minkowski_3d(f, t); });
}
