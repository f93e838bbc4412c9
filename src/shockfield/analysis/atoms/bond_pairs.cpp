#include "shockfield/analysis/atoms/bond_pairs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "shockfield/analysis/atoms/coordination.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

// Atom type from its bonds' indices: exactly the ideal sets, else other.
Structure type_from_bonds(const std::vector<int>& index, std::int64_t begin, std::int64_t end) {
  int n1421 = 0, n1422 = 0, n1441 = 0, n1661 = 0, n1551 = 0;
  for (std::int64_t b = begin; b < end; ++b) {
    switch (index[static_cast<std::size_t>(b)]) {
      case 1421: ++n1421; break;
      case 1422: ++n1422; break;
      case 1441: ++n1441; break;
      case 1661: ++n1661; break;
      case 1551: ++n1551; break;
      default: break;
    }
  }
  const auto bonds = end - begin;
  if (bonds == 12 && n1421 == 12) return Structure::fcc;
  if (bonds == 12 && n1421 == 6 && n1422 == 6) return Structure::hcp;
  if (bonds == 12 && n1551 == 12) return Structure::ico;
  if (bonds == 14 && n1661 == 8 && n1441 == 6) return Structure::bcc;
  return Structure::other;
}

}  // namespace

int honeycutt_andersen_index(const BondSignature& s) {
  if (s.common > 9 || s.bonds > 9) return 0;
  const int arrangement = (s.common == 4 && s.bonds == 2 && s.chain == 2) ? 2 : 1;
  return 1000 + 100 * s.common + 10 * s.bonds + arrangement;
}

BondPairResult BondPairAnalysis::compute(const AtomFrame& frame, const NeighborTable& table) const {
  if (!(cutoff > 0)) throw InputError(fmt::format("bond pairs: cutoff must be > 0 (got {})", cutoff));
  table.require(request(), "bond pairs");
  const double cut2 = cutoff * cutoff;
  const std::size_t n = frame.size();
  BondPairResult r;
  r.offset.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t bonds = neighbors_within(table, i, cut2);
    if (bonds > static_cast<std::size_t>(kMaxNeighbors))
      throw InputError(fmt::format("bond pairs: atom id {} has {} bonds within {} Å (at most {}): the cutoff is too "
                                   "large", frame.ids.empty() ? static_cast<std::int64_t>(i + 1) : frame.ids[i],
                                   bonds, cutoff, kMaxNeighbors));
    r.offset[i + 1] = r.offset[i] + static_cast<std::int64_t>(bonds);
  }
  r.partner.resize(static_cast<std::size_t>(r.offset[n]));
  r.index.resize(r.partner.size());
  r.structure.assign(n, Structure::other);
  for_each_atom(n, [&](std::size_t i, NeighborSetScratch& scratch) {
    const auto list = table.of(i);
    const auto begin = r.offset[i];
    const auto bonds = static_cast<std::size_t>(r.offset[i + 1] - begin);
    scratch.load(table, i, bonds);
    const auto masks = scratch.bond(bonds, cut2);
    for (std::size_t k = 0; k < bonds; ++k) {
      const auto b = static_cast<std::size_t>(begin) + k;
      r.partner[b] = table.owner(list[k]);
      r.index[b] = honeycutt_andersen_index(bond_signature(masks, static_cast<int>(k)));
    }
    r.structure[i] = type_from_bonds(r.index, begin, r.offset[i + 1]);
  });
  r.counts = count_structures(r.structure);
  return r;
}

}  // namespace shockfield::analysis::atoms
