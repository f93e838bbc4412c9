#pragma once
// Fuzz targets of the files a run or a bridge reads besides case, potential, atom, field and
// checkpoint files (targets.cpp): the run folder's checkpoint.case.toml and config.resolved.toml
// that --resume reads (resume_case), a material file referenced by an MPM or a PD case
// (material_file), and the bridges' inputs — the hugoniot_<stage>.toml and config.resolved.toml of
// MD Hugoniot run folders (bridge_eos), the --constants file of `bridge elastic` (bridge_elastic).
#include <functional>
#include <string>
#include <vector>

#include "targets.hpp"

namespace shockfield::fuzz {

/// The targets above whose name `wanted` accepts (resume_case makes a stopped run first).
std::vector<Target> file_targets(const Context& c, const std::function<bool(const std::string&)>& wanted);

}  // namespace shockfield::fuzz
