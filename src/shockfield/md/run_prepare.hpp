#pragma once
// The MD run's case, read and checked before the run folder exists (system, potential, stages,
// outputs; the refusals of what a tilted box or a barostat cannot do yet), and the fixes of a
// stage. Used by the run driver's MD plug-in (run_case.cpp).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/potential.hpp"
#include "shockfield/md/simulation.hpp"
#include "shockfield/md/system_builder.hpp"

namespace shockfield::md {

struct Prepared {
  BuiltSystem system;
  std::unique_ptr<Potential> potential;
  MdCase md;
  std::vector<std::uint32_t> stage_groups, add_groups;
  std::vector<std::string> notes;  ///< logged when the run starts
};

/// Everything read and checked, before the run folder exists.
Prepared prepare(const Config& root, const RunOptions& options);
/// The fixes of stage `s` on `group` (ensemble, piston, deform), replacing the previous stage's.
void add_stage_fixes(Simulation& sim, const StageSpec& s, std::uint32_t group, std::uint64_t seed);

}  // namespace shockfield::md
