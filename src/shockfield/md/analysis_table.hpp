#pragma once
// The per-atom analyses an MD case's [analysis] table asks for (docs/md.md), as the structure
// analysis of atoms takes them. Apart from the in-run diagnostic so that the case reader can check
// cluster_select before a run without linking the analyses themselves.
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/md/case_file.hpp"

namespace shockfield::md {

/// InputError when cluster_select is malformed or reads an analysis that is not in methods.
analysis::atoms::StructureAnalyses structure_analyses(const AnalysisSpec& spec);

}  // namespace shockfield::md
