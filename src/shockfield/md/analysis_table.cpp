#include "shockfield/md/analysis_table.hpp"

#include <fmt/format.h>

#include "shockfield/analysis/atoms/cluster_selection.hpp"

namespace shockfield::md {

namespace aa = analysis::atoms;

aa::StructureAnalyses structure_analyses(const AnalysisSpec& spec) {
  aa::StructureAnalyses analyses;
  for (const std::string& m : spec.methods) {
    if (m == "acna") analyses.adaptive_cna = aa::AdaptiveCna{};
    if (m == "cna") analyses.cna = aa::ConventionalCna{spec.cutoff};
    if (m == "csp") analyses.centro_symmetry = aa::CentroSymmetry{spec.csp_neighbors};
    if (m == "coordination") analyses.coordination = aa::Coordination{spec.cutoff};
    if (m == "bpa") analyses.bond_pairs = aa::BondPairAnalysis{spec.cutoff};
    if (m == "diamond") analyses.diamond = aa::DiamondCna{};
  }
  if (spec.clusters > 0) {
    analyses.select = aa::parse_cluster_selection(
        spec.cluster_select, analyses, spec.excess_energy, fmt::format("cluster_select \"{}\"", spec.cluster_select),
        [](const std::string& m) {
          return m == "excess" ? std::string("excess_energy = true") : fmt::format("\"{}\" in methods", m);
        });
    analyses.clusters = aa::DefectClusters{spec.clusters, spec.cluster_min_size};
  }
  return analyses;
}

}  // namespace shockfield::md
