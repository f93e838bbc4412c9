#pragma once
// Several per-atom analyses of one frame over one shared neighbour pass: the table is built once
// with the combined request of the analyses asked for, then each analysis reads it.
#include <functional>
#include <optional>
#include <vector>

#include "shockfield/analysis/atoms/bond_pairs.hpp"
#include "shockfield/analysis/atoms/centro_symmetry.hpp"
#include "shockfield/analysis/atoms/common_neighbor_analysis.hpp"
#include "shockfield/analysis/atoms/coordination.hpp"
#include "shockfield/analysis/atoms/defect_clusters.hpp"
#include "shockfield/analysis/atoms/diamond_structure.hpp"

namespace shockfield::analysis::atoms {

struct StructureAnalysisResult;

/// Which atoms to cluster, from the other analyses' results (one flag per atom).
using ClusterSelection = std::function<std::vector<bool>(const StructureAnalysisResult&)>;
/// Per-atom excess energy pe − e0 (eV) and the reference e0 it used.
struct ExcessEnergy {
  std::vector<double> excess;
  double reference = 0;  ///< e0, eV
};
/// Per-atom excess energy from the analyses' results — the caller's potential energies less a
/// reference that may depend on the structures (the median pe of the crystal atoms).
using ExcessEnergySource = std::function<ExcessEnergy(const StructureAnalysisResult&)>;

struct StructureAnalyses {
  std::optional<Coordination> coordination;
  std::optional<ConventionalCna> cna;
  std::optional<AdaptiveCna> adaptive_cna;
  std::optional<CentroSymmetry> centro_symmetry;
  std::optional<BondPairAnalysis> bond_pairs;
  std::optional<DiamondCna> diamond;
  /// Per-atom excess energy, computed after the analyses above and before the clusters (so that
  /// `select` can pick atoms by it); empty: none.
  ExcessEnergySource excess_energy;
  /// Clusters of the atoms `select` picks, computed after the analyses above on the same table.
  std::optional<DefectClusters> clusters;
  ClusterSelection select;

  bool empty() const {
    return !coordination && !cna && !adaptive_cna && !centro_symmetry && !bond_pairs && !diamond;
  }
  /// The neighbour request that serves every analysis asked for.
  NeighborRequest request() const;
};

struct StructureAnalysisResult {
  std::vector<int> coordination;            ///< empty unless asked for
  std::optional<StructureResult> cna;
  std::optional<StructureResult> adaptive_cna;
  std::vector<double> centro_symmetry;      ///< empty unless asked for
  std::optional<BondPairResult> bond_pairs;
  std::optional<DiamondResult> diamond;
  std::vector<double> excess_energy;        ///< eV; empty unless an excess_energy source is given
  std::optional<double> excess_reference;   ///< e0 of excess_energy, eV; set when a source is given
  std::optional<ClusterResult> clusters;
  std::size_t neighbor_table_bytes = 0;
};

/// The structures whose crystal atoms give the excess energy's reference: those of the first of
/// cna, acna, bpa that ran (the order of structures.csv); null when none ran.
const std::vector<Structure>* reference_structures(const StructureAnalysisResult& r);

/// Runs every analysis asked for on the frame (InputError when none is, or when clusters are
/// asked for without a selection).
StructureAnalysisResult analyze_structure(const AtomFrame& frame, const StructureAnalyses& analyses);

}  // namespace shockfield::analysis::atoms
