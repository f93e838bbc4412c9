#pragma once
// What an nphug stage reports (fixes/nphug.hpp): the extra thermo columns of a case with an nphug
// stage, and the Hugoniot state at the end of the stage (log line and summary.json
// `results.nphug`): the means over its second half, the shock and particle speeds of that state
// from the Rayleigh line, and how well the means satisfy the Rankine–Hugoniot energy relation.
#include <string>
#include <vector>

#include "shockfield/core/json.hpp"
#include "shockfield/md/diagnostics/hugoniot.hpp"
#include "shockfield/md/fixes/nphug.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

/// The nphug fix among the simulation's fixes, or nullptr.
const FixNphug* find_nphug(const Simulation& sim);

/// Extra thermo-table columns: PHug (the held pressure, bar), dHug (K), Us, Up (Å/ps), TTarget
/// (the thermostat's Hugoniot target, K); nan outside an nphug stage.
std::vector<std::string> nphug_thermo_columns();
std::vector<double> nphug_thermo_values(const Simulation& sim);

/// The state of an nphug stage when it ends.
struct NphugReport {
  std::string stage;
  std::string style;                ///< iso | aniso | x | y | z
  double target_pressure = 0;       ///< bar
  double v0 = 0, p0 = 0, e0 = 0;    ///< Å³, bar, eV
  double density0 = 0;              ///< g/cm³ at V₀
  NphugAverages mean;               ///< means over the second half (sums divided)
  double us = 0, up = 0;            ///< Å/ps, eq. (3) of nphug.hpp at the mean p and V
  double rh_lhs = 0, rh_rhs = 0;    ///< eV: ⟨E⟩ − E₀ and ½(⟨p⟩ + p₀)(V₀ − ⟨V⟩)
  NphugQuantities final_state;
  double final_temperature = 0;     ///< K
  std::size_t atoms = 0;
};

NphugReport make_nphug_report(const Simulation& sim, const FixNphug& fix, const std::string& stage);
/// One log line: P, ρ, V/V₀, T, U_s, U_p of the second half and the Rankine–Hugoniot residual.
std::string nphug_log_line(const NphugReport& r);
Json nphug_json(const NphugReport& r);
/// The second-half state as a Hugoniot point (hugoniot_<stage>.toml, read by `shockfield hugoniot
/// --method nphug` and the Hugoniot-to-EOS bridge); piston_speed is U_p.
HugoniotState nphug_hugoniot_state(const NphugReport& r);

}  // namespace shockfield::md
