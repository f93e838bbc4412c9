#include "shockfield/analysis/atoms/structure_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

NeighborRequest StructureAnalyses::request() const {
  NeighborRequest r;
  if (coordination) r = r.combined(coordination->request());
  if (cna) r = r.combined(cna->request());
  if (adaptive_cna) r = r.combined(adaptive_cna->request());
  if (centro_symmetry) r = r.combined(centro_symmetry->request());
  if (bond_pairs) r = r.combined(bond_pairs->request());
  if (diamond) r = r.combined(diamond->request());
  if (clusters) r = r.combined(clusters->request());
  return r;
}

const std::vector<Structure>* reference_structures(const StructureAnalysisResult& r) {
  if (r.cna) return &r.cna->structure;
  if (r.adaptive_cna) return &r.adaptive_cna->structure;
  if (r.bond_pairs) return &r.bond_pairs->structure;
  return nullptr;
}

StructureAnalysisResult analyze_structure(const AtomFrame& frame, const StructureAnalyses& analyses) {
  if (analyses.empty()) throw InputError("structure analysis: no analysis asked for");
  if (analyses.clusters && !analyses.select) throw InputError("structure analysis: clusters need a selection of atoms");
  StructureAnalysisResult out;
  if (frame.size() == 0) {  // nothing to search: empty results for what was asked
    if (analyses.excess_energy) out.excess_reference = NAN;
    if (analyses.cna) out.cna = StructureResult{};
    if (analyses.adaptive_cna) out.adaptive_cna = StructureResult{};
    if (analyses.bond_pairs) out.bond_pairs = BondPairResult{{0}, {}, {}, {}, {}};
    if (analyses.diamond) out.diamond = DiamondResult{};
    if (analyses.clusters) out.clusters = ClusterResult{};
    return out;
  }
  const NeighborTable table(frame, analyses.request());
  out.neighbor_table_bytes = table.memory_bytes();
  if (analyses.coordination) out.coordination = analyses.coordination->compute(frame, table);
  if (analyses.cna) out.cna = analyses.cna->compute(frame, table);
  if (analyses.adaptive_cna) out.adaptive_cna = analyses.adaptive_cna->compute(frame, table);
  if (analyses.centro_symmetry) out.centro_symmetry = analyses.centro_symmetry->compute(frame, table);
  if (analyses.bond_pairs) out.bond_pairs = analyses.bond_pairs->compute(frame, table);
  if (analyses.diamond) out.diamond = analyses.diamond->compute(frame, table);
  if (analyses.excess_energy) {
    ExcessEnergy e = analyses.excess_energy(out);
    out.excess_energy = std::move(e.excess);
    out.excess_reference = e.reference;
    if (out.excess_energy.size() != frame.size())
      throw InputError(fmt::format("structure analysis: {} excess energies for {} atoms", out.excess_energy.size(),
                                   frame.size()));
  }
  if (analyses.clusters) out.clusters = analyses.clusters->compute(frame, table, analyses.select(out));
  return out;
}

}  // namespace shockfield::analysis::atoms
