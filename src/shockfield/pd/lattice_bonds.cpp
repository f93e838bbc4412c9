#include "shockfield/pd/lattice_bonds.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shockfield::pd {

double lattice_bonds(int dim, const std::array<int, 3>& counts, double horizon_factor) {
  // The axes in use, the longest last (summed in closed form).
  std::array<double, 3> n{1.0, 1.0, 1.0};
  for (int d = 0; d < dim; ++d) n[static_cast<std::size_t>(d)] = counts[static_cast<std::size_t>(d)];
  std::sort(n.begin(), n.end());
  const double r2 = horizon_factor * horizon_factor * (1.0 + 1e-12);  // build_family's cut-off
  const auto reach = [&](double length, double room) {  // largest |o| along an axis
    return std::min(length - 1.0, std::floor(std::sqrt(std::max(0.0, room))));
  };
  double bonds = 0.0;
  const double a_max = reach(n[0], r2);
  for (double a = -a_max; a <= a_max; ++a) {
    const double b_max = reach(n[1], r2 - a * a);
    for (double b = -b_max; b <= b_max; ++b) {
      const double room = r2 - a * a - b * b;
      const double c_max = reach(n[2], room);
      // Σ_{|c| ≤ c_max} (n2 − |c|) = (2 c_max + 1) n2 − c_max (c_max + 1)
      const double along = (2.0 * c_max + 1.0) * n[2] - c_max * (c_max + 1.0);
      bonds += (n[0] - std::abs(a)) * (n[1] - std::abs(b)) * along;
    }
  }
  return bonds - n[0] * n[1] * n[2];  // o = 0 is the point itself
}

double pd_bytes(double points, double bonds) { return 1000.0 * points + 40.0 * bonds; }

}  // namespace shockfield::pd
