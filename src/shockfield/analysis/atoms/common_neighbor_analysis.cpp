#include "shockfield/analysis/atoms/common_neighbor_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/common_neighbors.hpp"
#include "shockfield/analysis/atoms/coordination.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

bool is(const BondSignature& s, int common, int bonds, int max_bond, int min_bond) {
  return s.common == common && s.bonds == bonds && s.max_bond == max_bond && s.min_bond == min_bond;
}

bool is(const BondSignature& s, int common, int bonds, int chain) {
  return s.common == common && s.bonds == bonds && s.chain == chain;
}

// LAMMPS cna/atom's rules on the bonded set of one atom (12 or 14 members).
Structure classify_lammps(std::span<const std::uint64_t> masks) {
  const int n = static_cast<int>(masks.size());
  int fcc = 0, hcp = 0, ico = 0, bcc4 = 0, bcc6 = 0;
  for (int j = 0; j < n; ++j) {
    const BondSignature s = bond_signature(masks, j);
    if (n == 12) {
      if (is(s, 4, 2, 1, 1)) ++fcc;
      else if (is(s, 4, 2, 2, 0)) ++hcp;
      else if (is(s, 5, 5, 2, 2)) ++ico;
    } else {
      if (is(s, 4, 4, 2, 2)) ++bcc4;
      else if (is(s, 6, 6, 2, 2)) ++bcc6;
    }
  }
  if (n == 12) {
    if (fcc == 12) return Structure::fcc;
    if (fcc == 6 && hcp == 6) return Structure::hcp;
    if (ico == 12) return Structure::ico;
  } else if (bcc4 == 6 && bcc6 == 8) {
    return Structure::bcc;
  }
  return Structure::other;
}

// Stukowski's (2012) rules on the loaded 12 (and, when there are, 14) nearest neighbours.
Structure classify_adaptive(NeighborSetScratch& scratch, bool has14) {
  constexpr double kFactor = (1.0 + std::numbers::sqrt2) / 2.0;
  const auto& v = scratch.vectors;
  // fcc, hcp, ico: the 12 nearest, r_c = (1+√2)/2 · mean distance.
  double sum12 = 0;
  for (std::size_t k = 0; k < 12; ++k) sum12 += v[k].norm();
  const double rc12 = kFactor * sum12 / 12.0;
  const auto masks12 = scratch.bond(12, rc12 * rc12);
  int fcc = 0, hcp = 0, ico = 0;
  for (int j = 0; j < 12; ++j) {
    const BondSignature s = bond_signature(masks12, j);
    if (is(s, 4, 2, 1)) ++fcc;
    else if (is(s, 4, 2, 2)) ++hcp;
    else if (is(s, 5, 5, 5)) ++ico;
  }
  if (fcc == 12) return Structure::fcc;
  if (fcc == 6 && hcp == 6) return Structure::hcp;
  if (ico == 12) return Structure::ico;
  if (!has14) return Structure::other;
  // bcc: the 14 nearest (8 first-shell at √3/2 a, 6 second-shell at a).
  double sum8 = 0, sum6 = 0;
  for (std::size_t k = 0; k < 8; ++k) sum8 += v[k].norm();
  for (std::size_t k = 8; k < 14; ++k) sum6 += v[k].norm();
  const double rc14 = kFactor * (2.0 / std::sqrt(3.0) * sum8 + sum6) / 14.0;
  const auto masks14 = scratch.bond(14, rc14 * rc14);
  int bcc6 = 0, bcc4 = 0;
  for (int j = 0; j < 14; ++j) {
    const BondSignature s = bond_signature(masks14, j);
    if (is(s, 6, 6, 6)) ++bcc6;
    else if (is(s, 4, 4, 4)) ++bcc4;
  }
  return bcc6 == 8 && bcc4 == 6 ? Structure::bcc : Structure::other;
}

StructureResult finish(std::vector<Structure> structure) {
  StructureResult r;
  r.counts = count_structures(structure);
  r.structure = std::move(structure);
  return r;
}

}  // namespace

StructureResult ConventionalCna::compute(const AtomFrame& frame, const NeighborTable& table) const {
  if (!(cutoff > 0)) throw InputError(fmt::format("cna: cutoff must be > 0 (got {})", cutoff));
  table.require(request(), "cna");
  const double cut2 = cutoff * cutoff;
  std::vector<Structure> structure(frame.size(), Structure::other);
  for_each_atom(frame.size(), [&](std::size_t i, NeighborSetScratch& scratch) {
    const std::size_t bonded = neighbors_within(table, i, cut2);
    if (bonded != 12 && bonded != 14) return;
    scratch.load(table, i, bonded);
    structure[i] = classify_lammps(scratch.bond(bonded, cut2));
  });
  return finish(std::move(structure));
}

StructureResult AdaptiveCna::compute(const AtomFrame& frame, const NeighborTable& table) const {
  table.require(request(), "adaptive cna");
  std::vector<Structure> structure(frame.size(), Structure::other);
  for_each_atom(frame.size(), [&](std::size_t i, NeighborSetScratch& scratch) {
    const std::size_t available = table.of(i).size();
    if (available < 12) return;
    scratch.load(table, i, std::min<std::size_t>(available, 14));
    structure[i] = classify_adaptive(scratch, available >= 14);
  });
  return finish(std::move(structure));
}

}  // namespace shockfield::analysis::atoms
