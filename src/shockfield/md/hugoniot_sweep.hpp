#pragma once
// A U_s–U_p sweep (`shockfield hugoniot`): an MD case with one stage of the sweep's method is run
// once per value into FOLDER/<prefix>_<value>/ — method piston: one [stage.piston], the values
// piston speeds (RunOptions::piston_speed), folders up_<speed>; msst: one msst stage, the values
// shock speeds (--set stage[k].msst.shock_speed), folders us_<speed>; nphug: one nphug stage, the
// values pressures in GPa (--set stage[k].nphug.pressure), folders p_<GPa>. Each run's Hugoniot
// state (hugoniot_<stage>.toml, written by run_case) is collected, with for a piston its front
// track (shock_front_<stage>.csv, whose fit residuals give the standard error of U_s; nan for msst
// and nphug, whose states are time averages), U_s = c0 + s·U_p is fitted, and
// FOLDER/hugoniot_sweep.csv and FOLDER/hugoniot_fit.toml are written. A finished run already in
// its folder is reused unless `overwrite`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/line_fit.hpp"

namespace shockfield::md {

/// Experimental copper Hugoniot, U_s = 3.940 + 1.489 U_p (km/s): S. P. Marsh (ed.), LASL Shock
/// Hugoniot Data, University of California Press (1980), copper; consistent with A. C. Mitchell
/// & W. J. Nellis, J. Appl. Phys. 52, 3363 (1981).
inline constexpr double kCopperC0 = 3.940, kCopperS = 1.489;

struct HugoniotSweepSettings {
  std::filesystem::path case_file;
  std::string method = "piston";  ///< piston | msst | nphug
  std::vector<double> speeds;  ///< piston (piston) or shock (msst) speeds, km/s; pressures (nphug), GPa
  std::filesystem::path folder;
  bool overwrite = false;
  bool quiet = false;          ///< no progress lines from the runs
};

struct SweepPoint {
  double piston = 0;                  ///< the swept value: piston or shock speed (km/s), pressure (GPa)
  double up = 0, us = 0;              ///< km/s
  double us_stderr = 0;               ///< km/s, from the front-position fit residuals
  double front_rms = 0;               ///< Å, rms residual of the front about its line
  double pressure = 0, pressure_rh = 0, density = 0, temperature = 0;  ///< GPa, GPa, g/cm³, K
};

struct HugoniotSweep {
  std::string stage;               ///< the swept stage's name
  std::vector<SweepPoint> points;  ///< in increasing piston speed
  std::optional<analysis::UsUpFit> fit;      ///< with two or more speeds
};

/// Runs (or reuses) every speed and writes the sweep files; InputError for a case without
/// exactly one piston stage or without profiles, RunError for a run without a Hugoniot state.
HugoniotSweep run_hugoniot_sweep(HugoniotSweepSettings settings);

}  // namespace shockfield::md
