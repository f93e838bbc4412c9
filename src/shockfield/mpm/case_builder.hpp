#pragma once
// Builds the sample of an MPM case file: the particles of every [[body]] (blocks, porous bodies,
// single cavities, the mirrored partner of a symmetric impact), with geometric errors reported
// against the case file's keys (a body outside the grid, a porosity that cannot be packed, a
// cavity outside its body, a body not touching its wall).
#include <optional>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/mpm/case_file.hpp"
#include "shockfield/mpm/particles.hpp"

namespace shockfield::mpm {

struct BuiltSample {
  Particles particles;
  std::vector<BodyStats> stats;   ///< one per [[body]] (a symmetric partner is counted in its body)
  std::optional<Void> cavity;     ///< the first body's cavity, followed by the cavity diagnostics
  double cavity_spacing = 0.0;    ///< particle spacing of that body [m]
};

/// InputError naming the offending [[body]] key when the geometry is impossible.
BuiltSample build_sample(const MpmCase& c, const Config& root);

}  // namespace shockfield::mpm
