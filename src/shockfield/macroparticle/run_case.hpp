#pragma once
// `method = "macroparticle"` as a plug-in of the run driver (core/method.hpp): the macroscopic
// particle model of Saitoh et al. on the MD engine — a rod or box of particles loaded in tension
// or compression, its thermo table (strain, stress, E and ν estimates), dumps, VTK particles and
// checkpoints (md's, so a resumed run continues bitwise). Case keys: docs/macroparticle.md.
#include <memory>

#include "shockfield/core/method.hpp"

namespace shockfield::macroparticle {

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);

}  // namespace shockfield::macroparticle
