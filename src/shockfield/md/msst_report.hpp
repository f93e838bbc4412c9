#pragma once
// What an MSST stage reports (fixes/msst.hpp): the extra thermo columns of a case with an msst
// stage, the state at the end of the stage (log line and summary.json `results.msst`), with the
// Hugoniot state averaged over the second half of the stage and the drift of the conserved
// quantity.
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/json.hpp"
#include "shockfield/md/diagnostics/hugoniot.hpp"
#include "shockfield/md/fixes/msst.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

/// The MSST fix among the simulation's fixes, or nullptr.
const FixMsst* find_msst(const Simulation& sim);

/// Extra thermo-table columns: Vol (Å³), Pshock (P_aa, bar), Econs (eV, K + U + the fix's
/// energy), Up (Å/ps), dHug (K), dRay (bar), LagPos (Å). The last four are nan outside an msst
/// stage; Pshock is then the component along `axis`.
std::vector<std::string> msst_thermo_columns();
std::vector<double> msst_thermo_values(const Simulation& sim, int axis);

/// The state of an msst stage when it ends.
struct MsstReport {
  std::string stage;
  double shock_speed = 0;       ///< km/s
  double v0 = 0, p0 = 0, e0 = 0;  ///< Å³, bar, eV
  double density0 = 0;          ///< g/cm³ at V₀
  MsstQuantities final_state;
  double final_temperature = 0; ///< K
  MsstAverages mean;            ///< means over the second half of the stage (sums divided)
  double conserved_start = 0, conserved_end = 0;  ///< eV
  std::size_t atoms = 0;
};

MsstReport make_msst_report(const Simulation& sim, const FixMsst& fix, const std::string& stage);
/// One log line: U_p, P, ρ, T of the second half and the conserved-quantity drift.
std::string msst_log_line(const MsstReport& r);
Json msst_json(const MsstReport& r);
/// The second-half state as a Hugoniot point (hugoniot_<stage>.toml, read by `shockfield hugoniot
/// --method msst` and the Hugoniot-to-EOS bridge); piston_speed is U_p, the speed of the piston
/// that would drive this shock.
HugoniotState msst_hugoniot_state(const MsstReport& r);

}  // namespace shockfield::md
