#include "shockfield/analysis/atoms/coordination.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

std::size_t neighbors_within(const NeighborTable& table, std::size_t i, double cutoff2) {
  const auto list = table.of(i);
  std::size_t count = 0;
  while (count < list.size() && table.delta(i, list[count]).squaredNorm() < cutoff2) ++count;
  return count;
}

std::vector<int> Coordination::compute(const AtomFrame& frame, const NeighborTable& table) const {
  if (!(cutoff > 0)) throw InputError(fmt::format("coordination: cutoff must be > 0 (got {})", cutoff));
  table.require(request(), "coordination");
  std::vector<int> count(frame.size(), 0);
  const auto n = static_cast<std::ptrdiff_t>(frame.size());
  const double cut2 = cutoff * cutoff;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t a = 0; a < n; ++a)
    count[static_cast<std::size_t>(a)] = static_cast<int>(neighbors_within(table, static_cast<std::size_t>(a), cut2));
  return count;
}

}  // namespace shockfield::analysis::atoms
