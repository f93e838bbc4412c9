#include "shockfield/analysis/atoms/diamond_structure.hpp"

#include <numbers>

#include "shockfield/analysis/atoms/common_neighbors.hpp"

namespace shockfield::analysis::atoms {
namespace {

// The 12 second neighbours of atom i from the 4 nearest of i and of each of them (v_i + v_ij with
// j ≠ the centre); false unless each neighbour gives exactly 3.
bool second_neighbours(const NeighborTable& table, std::size_t i, std::array<Vec3, kMaxNeighbors>& out) {
  const auto first = table.of(i);
  if (first.size() < 4) return false;
  std::size_t n = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const Vec3 v0 = table.delta(i, first[k]);
    const auto atom = static_cast<std::size_t>(table.owner(first[k]));
    const auto theirs = table.of(atom);
    if (theirs.size() < 4) return false;
    std::size_t added = 0;
    for (std::size_t j = 0; j < 4; ++j) {
      const Vec3 v = v0 + table.delta(atom, theirs[j]);
      if (v.squaredNorm() < 1e-2 * v0.squaredNorm()) continue;  // back to the centre
      if (n == 12) return false;
      out[n++] = v;
      ++added;
    }
    if (added != 3) return false;
  }
  return n == 12;
}

DiamondStructure classify(NeighborSetScratch& scratch) {
  double sum = 0;
  for (std::size_t k = 0; k < 12; ++k) sum += scratch.vectors[k].norm();
  const double rc = (1.0 + std::numbers::sqrt2) / 2.0 * sum / 12.0;
  const auto masks = scratch.bond(12, rc * rc);
  int n421 = 0, n422 = 0;
  for (int j = 0; j < 12; ++j) {
    const BondSignature s = bond_signature(masks, j);
    if (s.common != 4 || s.bonds != 2) return DiamondStructure::other;
    if (s.chain == 1) ++n421;
    else if (s.chain == 2) ++n422;
  }
  if (n421 == 12) return DiamondStructure::cubic;
  if (n421 == 6 && n422 == 6) return DiamondStructure::hexagonal;
  return DiamondStructure::other;
}

// Marks the unidentified atoms among the 4 nearest of each atom of kind `from` as `to_cubic` or
// `to_hexagonal` (by the kind of the atom they border), in atom order.
void mark_neighbours(const NeighborTable& table, std::vector<DiamondStructure>& s, DiamondStructure cubic_from,
                     DiamondStructure hex_from, DiamondStructure to_cubic, DiamondStructure to_hex) {
  const std::vector<DiamondStructure> before = s;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (before[i] != cubic_from && before[i] != hex_from) continue;
    const auto first = table.of(i);
    for (std::size_t k = 0; k < 4 && k < first.size(); ++k) {
      DiamondStructure& t = s[static_cast<std::size_t>(table.owner(first[k]))];
      if (t == DiamondStructure::other) t = before[i] == cubic_from ? to_cubic : to_hex;
    }
  }
}

}  // namespace

DiamondResult DiamondCna::compute(const AtomFrame& frame, const NeighborTable& table) const {
  table.require(request(), "diamond structure");
  DiamondResult r;
  r.structure.assign(frame.size(), DiamondStructure::other);
  for_each_atom(frame.size(), [&](std::size_t i, NeighborSetScratch& scratch) {
    if (second_neighbours(table, i, scratch.vectors)) r.structure[i] = classify(scratch);
  });
  using D = DiamondStructure;
  mark_neighbours(table, r.structure, D::cubic, D::hexagonal, D::cubic_first, D::hexagonal_first);
  mark_neighbours(table, r.structure, D::cubic_first, D::hexagonal_first, D::cubic_second, D::hexagonal_second);
  for (D s : r.structure) ++r.count[static_cast<std::size_t>(s)];
  return r;
}

}  // namespace shockfield::analysis::atoms
