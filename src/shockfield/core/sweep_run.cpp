#include "shockfield/core/sweep_run.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "shockfield/core/error.hpp"

namespace shockfield {

Config sweep_point_state(const std::filesystem::path& state, const RunOptions& r, std::string_view method,
                         const std::function<void(const Config&, const RunOptions&)>& run, const std::string& what) {
  if (r.overwrite || !std::filesystem::exists(state)) {
    const Config root = Config::load(r.case_file, r.overrides);
    root.get_choice("method", {std::string(method)});  // read here as `shockfield run` does, so it is a known key
    run(root, r);
  } else {
    std::printf("%s: reusing the finished run in %s\n", what.c_str(), state.parent_path().string().c_str());
  }
  const Config h = Config::load(state);
  if (!h.get_bool("complete"))
    throw RunError(fmt::format("{}: no complete Hugoniot state at {} ({})", state.string(), what, h.get_string("note")));
  return h;
}

}  // namespace shockfield
