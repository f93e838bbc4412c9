#include "shockfield/md/diagnostics/structure.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/md/analysis_table.hpp"

namespace shockfield::md {

namespace aa = analysis::atoms;

StructureDiagnostic::StructureDiagnostic(const AnalysisSpec& spec) : analyses_(structure_analyses(spec)) {}

std::vector<std::string> StructureDiagnostic::columns() const {
  std::vector<std::string> c{"step", "time_ps", "atoms"};
  for (std::string& name : aa::structure_count_columns(analyses_)) c.push_back(std::move(name));
  return c;
}

aa::StructureAnalysisResult StructureDiagnostic::compute(const Simulation& sim) const {
  const aa::AtomFrame frame =
      aa::frame_from_atoms(sim.step, sim.box, sim.atoms, fmt::format("[analysis] at step {}", sim.step));
  return aa::analyze_structure(frame, analyses_);
}

std::vector<double> StructureDiagnostic::row(const Simulation& sim, const aa::StructureAnalysisResult& r) const {
  std::vector<double> values{static_cast<double>(sim.step), sim.time, static_cast<double>(sim.atoms.nlocal)};
  for (double v : aa::structure_count_values(r)) values.push_back(v);
  return values;
}

}  // namespace shockfield::md
