// Uses the installed shockfield library: the Minkowski functionals of a disk of radius 20 cells
// on a 64² grid (one component, χ = 1; area fraction = the disk's cells / 64²). Prints
// "euler 1 area_fraction <A>" for tests/cli/install.sh.
#include <cstdio>
#include <vector>

#include "shockfield/analysis/minkowski.hpp"

int main() {
  namespace sa = shockfield::analysis;
  sa::GridField f = sa::GridField::filled(64, 64, 1, 0.0);
  for (std::size_t y = 0; y < 64; ++y)
    for (std::size_t x = 0; x < 64; ++x) {
      const double dx = double(x) - 31.5, dy = double(y) - 31.5;
      if (dx * dx + dy * dy <= 400.0) f.values[f.index(x, y)] = 1.0;
    }
  const std::vector<double> thresholds{0.5};
  const auto m = sa::minkowski_2d(f, thresholds);
  std::printf("euler %lld area_fraction %.6f\n", static_cast<long long>(m[0].euler), m[0].area_fraction);
  return m[0].euler == 1 ? 0 : 1;
}
