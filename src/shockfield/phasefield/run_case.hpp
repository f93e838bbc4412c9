#pragma once
// `method = "phasefield"`: the Ginzburg–Landau phase-domain model (solver.hpp) as a plug-in of
// the run driver (core/method.hpp): series.csv (step, time, hcp volume fraction, free energy, hcp
// volume, equivalent radius), field frames (fields/xi_K.vti, fields.pvd), thermo table,
// checkpoint.h5 (--resume continues bitwise). docs/phasefield.md lists the keys.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield::phasefield {

/// Reads, validates and derives the case (the factory of the run driver's registry).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);

}  // namespace shockfield::phasefield
