#include "shockfield/md/diagnostics/structure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/analysis/atoms/structure_profile.hpp"
#include "shockfield/md/analysis_table.hpp"

namespace shockfield::md {

namespace aa = analysis::atoms;

StructureDiagnostic::StructureDiagnostic(const AnalysisSpec& spec)
    : analyses_(structure_analyses(spec)), excess_reference_(spec.excess_reference) {
  if (!spec.excess_energy) return;
  excess_crystal_ = spec.excess_crystal == "hcp" ? aa::Structure::hcp
                    : spec.excess_crystal == "bcc" ? aa::Structure::bcc
                                                   : aa::Structure::fcc;
  analyses_.excess_energy = [](const aa::StructureAnalysisResult&) -> aa::ExcessEnergy {
    throw std::logic_error("StructureDiagnostic: the excess energy is computed per frame");
  };
}

// pe − e0 of the force evaluation's per-atom energies (Xu et al. 2015 §3.2.3). A frame without an
// atom of the crystal (melted, transformed) has no `auto` reference: NaN, not a stopped run.
aa::ExcessEnergy StructureDiagnostic::excess_of(const Simulation& sim, const aa::StructureAnalysisResult& r) const {
  const std::size_t n = sim.atoms.nlocal;
  if (!sim.forces.per_atom || sim.forces.energy_atom.size() < n)
    throw std::logic_error(fmt::format("[analysis] at step {}: the excess energy needs per-atom energies", sim.step));
  const std::vector<double> pe(sim.forces.energy_atom.begin(), sim.forces.energy_atom.begin() + static_cast<std::ptrdiff_t>(n));
  const std::vector<aa::Structure>* structures = aa::reference_structures(r);
  if (excess_reference_) return aa::excess_energy(pe, std::vector<aa::Structure>(n, excess_crystal_), excess_crystal_, &*excess_reference_);
  if (std::find(structures->begin(), structures->end(), excess_crystal_) == structures->end())
    return {std::vector<double>(n, NAN), NAN};
  return aa::excess_energy(pe, *structures, excess_crystal_);
}

std::vector<std::string> StructureDiagnostic::columns() const {
  std::vector<std::string> c{"step", "time_ps", "atoms"};
  for (std::string& name : aa::structure_count_columns(analyses_)) c.push_back(std::move(name));
  return c;
}

aa::StructureAnalysisResult StructureDiagnostic::compute(const Simulation& sim) const {
  const aa::AtomFrame frame =
      aa::frame_from_atoms(sim.step, sim.box, sim.atoms, fmt::format("[analysis] at step {}", sim.step));
  if (!excess_energy()) return aa::analyze_structure(frame, analyses_);
  aa::StructureAnalyses analyses = analyses_;
  analyses.excess_energy = [&](const aa::StructureAnalysisResult& r) { return excess_of(sim, r); };
  return aa::analyze_structure(frame, analyses);
}

std::vector<double> StructureDiagnostic::row(const Simulation& sim, const aa::StructureAnalysisResult& r) const {
  std::vector<double> values{static_cast<double>(sim.step), sim.time, static_cast<double>(sim.atoms.nlocal)};
  for (double v : aa::structure_count_values(r)) values.push_back(v);
  return values;
}

}  // namespace shockfield::md
