#pragma once
// The GLS liquid–vapour part of a `method = "dbm"` run (docs/dbm.md): the force installed on the
// simulation, the quench start, the phase-separation series (Xu et al. 2015, §4.3: D, D^F, D^G of eqs.
// 29–31 and 35, L(t), R(t), density range, largest |u|, mass, e_T), the D fields of the frames,
// and summary.csv with t_SD and D_max (peak of D(t)), the peak of L(t) and u_DG, read back from
// series.csv so a resumed run summarises the whole history.
#include <filesystem>
#include <string>
#include <vector>

#include "shockfield/core/json.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/gls.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::dbm {

class GlsRunPart {
 public:
  GlsRunPart(Simulation& sim, const DbmCase& c);

  /// f = f^eq of the quench on every cell.
  void initialize(Simulation& sim) const;
  /// The columns of series_row; L_rho<level> per extra threshold.
  std::vector<std::string> series_columns() const;
  std::vector<double> series_row(const Simulation& sim);
  /// D and D^F (eq. 35 of Δ* and Δ*^F) per cell, for the field frames.
  std::vector<io::VtkArray> field_arrays();
  /// What makes GLS runs break down and what to change (logged when one does).
  static const char* blow_up_hint();

 private:
  Simulation& sim_;
  GlsForce force_;
  GlsCaseSpec spec_;
};

/// The phase-separation measures of a run's series (Xu et al. 2015, §4.3).
struct PhaseSummary {
  SpinodalEnd net, force;  // peaks of D (t_SD, D_max, R_SD) and of L; peak of D^F
  DomainGrowth growth;     // u_DG over [t_SD, t_SD + growth_window]
};

/// summary.csv of a GLS run folder from its series.csv: t_SD, R_SD and D_max (peak of D), the peak of
/// D^F (t_SD_force, D_force_max) and of L (t_L_max, L_max), and u_DG, the slope of R(t) over
/// [t_DG_begin, t_DG_end] = [t_SD, t_SD + spec.growth_window] (domain_growth); the values are also logged.
PhaseSummary write_phase_summary(const std::filesystem::path& folder, const GlsCaseSpec& spec, Logger& log);

/// The summary as summary.json's results "phase_separation" (so a sweep's CSV has a column of each).
Json phase_summary_json(const PhaseSummary& s);

}  // namespace shockfield::dbm
