#include "shockfield/analysis/atoms/centro_symmetry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "shockfield/analysis/atoms/common_neighbors.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

int CentroSymmetry::parse_neighbors(const std::string& text, const std::string& what) {
  if (text == "fcc") return 12;
  if (text == "bcc") return 8;
  int n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc{} || end != text.data() + text.size() || n < 2 || n > kMaxNeighbors || n % 2 != 0)
    throw InputError(fmt::format("{}: expected fcc, bcc or an even neighbour count 2..{}, got '{}'", what,
                                 kMaxNeighbors, text));
  return n;
}

std::vector<double> CentroSymmetry::compute(const AtomFrame& frame, const NeighborTable& table) const {
  if (neighbors < 2 || neighbors > kMaxNeighbors || neighbors % 2 != 0)
    throw InputError(fmt::format("centro-symmetry: neighbour count must be even and 2..{} (got {})", kMaxNeighbors,
                                 neighbors));
  table.require(request(), "centro-symmetry");
  const auto nn = static_cast<std::size_t>(neighbors);
  std::vector<double> csp(frame.size(), 0.0);
  const auto n = static_cast<std::ptrdiff_t>(frame.size());
#pragma omp parallel
  {
    std::vector<Vec3> r(nn);
    std::vector<double> pairs(nn * (nn - 1) / 2);
#pragma omp for schedule(static)
    for (std::ptrdiff_t a = 0; a < n; ++a) {
      const auto i = static_cast<std::size_t>(a);
      const auto list = table.of(i);
      if (list.size() < nn) continue;  // fewer than N neighbours: 0, as LAMMPS
      for (std::size_t k = 0; k < nn; ++k) r[k] = table.delta(i, list[k]);
      std::size_t m = 0;
      for (std::size_t j = 0; j < nn; ++j)
        for (std::size_t k = j + 1; k < nn; ++k) pairs[m++] = (r[j] + r[k]).squaredNorm();
      // The N/2 smallest, summed in increasing order (thread-independent).
      std::partial_sort(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(nn / 2), pairs.end());
      double sum = 0;
      for (std::size_t k = 0; k < nn / 2; ++k) sum += pairs[k];
      csp[i] = sum;
    }
  }
  return csp;
}

}  // namespace shockfield::analysis::atoms
