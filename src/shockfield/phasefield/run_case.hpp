#pragma once
// `method = "phasefield"`: the Ginzburg–Landau phase-domain model (solver.hpp) as a plug-in of
// the run driver (core/method.hpp): series.csv (step, time, hcp volume fraction, free energy, hcp
// volume, equivalent radius), field frames (fields/xi_K.vti, fields.pvd), thermo table,
// checkpoint.h5 (--resume continues bitwise). docs/phasefield.md lists the keys.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/phasefield/grid.hpp"

namespace shockfield::phasefield {

/// Reads, validates and derives the case (the factory of the run driver's registry).
/// `[model] kind = "sharp_front"` goes to make_sharp_front_method (sharp_front_case.hpp).
std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options);

/// Writes frame k of ξ on the grid's nodes as fields/xi_K.vti under `folder` and indexes it in `pvd`.
void write_xi_frame(const std::filesystem::path& folder, const Grid& grid, const std::vector<double>& xi,
                    std::int64_t k, const io::VtkFormat& format, double time, io::PvdSeries& pvd);

}  // namespace shockfield::phasefield
