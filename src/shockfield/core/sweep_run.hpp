#pragma once
// One point of a Hugoniot sweep (`shockfield hugoniot`, md/ and mpm/hugoniot_sweep): run the case
// into its folder unless the Hugoniot state file is there already, then read that state.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield {

/// With r.overwrite or without `state`, loads r.case_file with r.overrides, reads its `method` key
/// (which must be `method`) and calls `run`; otherwise says it reuses the finished run. Returns the
/// loaded `state`; RunError when its `complete` is false, naming `what` (the swept value) and its note.
Config sweep_point_state(const std::filesystem::path& state, const RunOptions& r, std::string_view method,
                         const std::function<void(const Config&, const RunOptions&)>& run, const std::string& what);

}  // namespace shockfield
