#include "shockfield/analysis/atoms/common_neighbors.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "shockfield/core/simd_clones.hpp"

namespace shockfield::analysis::atoms {

void bond_masks(std::span<const Vec3> vectors, double cutoff2, std::span<std::uint64_t> masks) {
  const std::size_t n = vectors.size();
  if (n > static_cast<std::size_t>(kMaxNeighbors) || masks.size() < n)
    throw std::length_error("bond_masks: more neighbours than kMaxNeighbors");
  std::fill(masks.begin(), masks.begin() + static_cast<std::ptrdiff_t>(n), 0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j + 1; k < n; ++k)
      if ((vectors[j] - vectors[k]).squaredNorm() < cutoff2) {
        masks[j] |= std::uint64_t{1} << k;
        masks[k] |= std::uint64_t{1} << j;
      }
}

// Cloned for x86-64-v3 (core/simd_clones.hpp): its POPCNT and TZCNT instructions replace the
// baseline build's library popcount, 5 % of an analysis (bench/RESULTS.md); results are integers,
// the same in every clone.
SHOCKFIELD_SIMD_CLONES BondSignature bond_signature(std::span<const std::uint64_t> masks, int j) {
  BondSignature s;
  const std::uint64_t common = masks[static_cast<std::size_t>(j)];
  s.common = std::popcount(common);
  if (s.common == 0) return s;
  s.min_bond = kMaxNeighbors;
  int degree_sum = 0;
  for (std::uint64_t rest = common; rest; rest &= rest - 1) {
    const int b = std::popcount(masks[static_cast<std::size_t>(std::countr_zero(rest))] & common);
    degree_sum += b;
    s.max_bond = std::max(s.max_bond, b);
    s.min_bond = std::min(s.min_bond, b);
  }
  s.bonds = degree_sum / 2;
  // Largest connected group of bonds among the common neighbours: flood each component.
  for (std::uint64_t unvisited = common; unvisited;) {
    std::uint64_t component = unvisited & (~unvisited + 1), frontier = component;
    while (frontier) {
      const int k = std::countr_zero(frontier);
      frontier &= frontier - 1;
      const std::uint64_t next = masks[static_cast<std::size_t>(k)] & common & ~component;
      component |= next;
      frontier |= next;
    }
    unvisited &= ~component;
    int component_degrees = 0;
    for (std::uint64_t rest = component; rest; rest &= rest - 1)
      component_degrees += std::popcount(masks[static_cast<std::size_t>(std::countr_zero(rest))] & component);
    s.chain = std::max(s.chain, component_degrees / 2);
  }
  return s;
}

}  // namespace shockfield::analysis::atoms
