#pragma once
// A U_s–u_p sweep of an MPM case (`shockfield hugoniot --method mpm`): the case, with wall or
// symmetric loading and [shock_front] on, runs once per loading speed into FOLDER/up_<km/s>/
// (--set loading.speed); each run's hugoniot_<material>.toml (shock_front_output.hpp) is
// collected, U_s = c0 + s·u_p is fitted (analysis::fit_us_up) and FOLDER/hugoniot_sweep.csv and
// FOLDER/hugoniot_fit.toml are written in SI, the fit beside the linear Hugoniot of the profiled
// body's material (c0, λ of its Mie–Grüneisen EOS). A finished run already in its folder is
// reused unless `overwrite`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/line_fit.hpp"

namespace shockfield::mpm {

struct MpmSweepPoint {
  double speed = 0;                   ///< loading speed [m/s]
  double up = 0, us = 0, us_stderr = 0;  ///< [m/s]
  double stress = 0, stress_rh = 0;   ///< σ_aa on the plateau and from the jump conditions [Pa]
  double density = 0, density_rh = 0; ///< bulk density on the plateau and from the jump conditions [kg/m³]
  double temperature = 0;             ///< [K]
};

struct MpmHugoniotSweep {
  std::string material;                  ///< the profiled body's material
  double c0 = 0, lambda = 0;             ///< its EOS's linear Hugoniot U_s = c0 + λ u_p [m/s, 1]
  std::vector<MpmSweepPoint> points;     ///< in increasing speed
  std::optional<analysis::UsUpFit> fit;        ///< with two or more speeds (c0 in m/s)
};

/// `speeds` in m/s. InputError for a case that is not an MPM case with [shock_front] and wall or
/// symmetric loading; RunError for a run without a complete Hugoniot state.
MpmHugoniotSweep run_mpm_hugoniot_sweep(const std::filesystem::path& case_file, std::vector<double> speeds,
                                        const std::filesystem::path& folder, bool overwrite, bool quiet);

}  // namespace shockfield::mpm
