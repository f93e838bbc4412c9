#pragma once
// Common-neighbour signatures of bonds (Honeycutt & Andersen 1987; Faken & Jónsson 1994), the
// kernel shared by conventional CNA, adaptive CNA (Stukowski 2012) and bond-pair analysis.
// Given a central atom's neighbour set S (vectors from it, at most kMaxNeighbors) and a bond
// cutoff r_c, two members of S are bonded when |v_j − v_k| < r_c. For the bond to neighbour j:
//   common        members of S bonded to j (the common neighbours of the centre and j);
//   bonds         bonds among those common neighbours;
//   max/min_bond  the most/fewest bonds any common neighbour has among them (LAMMPS cna/atom);
//   chain         bonds in the largest connected group of those bonds (OVITO's n_lcb).
#include <array>
#include <cstdint>
#include <span>

#include "shockfield/analysis/atoms/neighbor_table.hpp"
#include "shockfield/core/types.hpp"

namespace shockfield::analysis::atoms {

constexpr int kMaxNeighbors = 64;

struct BondSignature {
  int common = 0, bonds = 0, max_bond = 0, min_bond = 0, chain = 0;
};

/// bit k of masks[j]: members j and k of `vectors` are closer than sqrt(cutoff2).
/// Throws std::length_error when vectors has more than kMaxNeighbors entries.
void bond_masks(std::span<const Vec3> vectors, double cutoff2, std::span<std::uint64_t> masks);

/// The signature of the bond from the centre to member j of a set with the given bond masks.
BondSignature bond_signature(std::span<const std::uint64_t> masks, int j);

/// Per-thread work arrays of a neighbour-set analysis.
struct NeighborSetScratch {
  std::array<Vec3, kMaxNeighbors> vectors;
  std::array<std::uint64_t, kMaxNeighbors> masks;

  /// Loads the vectors to the first `count` (<= kMaxNeighbors) neighbours of atom i.
  void load(const NeighborTable& table, std::size_t i, std::size_t count) {
    const auto list = table.of(i);
    for (std::size_t k = 0; k < count; ++k) vectors[k] = table.delta(i, list[k]);
  }
  /// Bond masks of the loaded first `count` vectors at the given squared cutoff.
  std::span<const std::uint64_t> bond(std::size_t count, double cutoff2) {
    bond_masks({vectors.data(), count}, cutoff2, masks);
    return {masks.data(), count};
  }
};

/// visit(i, scratch) for every atom i < n: OpenMP over atoms, static schedule, one scratch per
/// thread. Each atom's result depends on its own data only, so on no thread count.
template <class Visit>
void for_each_atom(std::size_t n, Visit&& visit) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel
  {
    NeighborSetScratch scratch;
#pragma omp for schedule(static)
    for (std::ptrdiff_t a = 0; a < count; ++a) visit(static_cast<std::size_t>(a), scratch);
  }
}

}  // namespace shockfield::analysis::atoms
