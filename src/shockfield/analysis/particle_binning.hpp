#pragma once
// Particles to field: a particle quantity (temperature, density, velocity component of MPM or MD
// particles) binned onto a regular grid so the grid analyses apply. Cells that receive no
// particle are marked void (no material: a pore, a free surface, a gap).
#include <span>

#include "shockfield/analysis/grid_field.hpp"
#include "shockfield/core/types.hpp"

namespace shockfield::analysis {

enum class BinReduction {
  mean,  ///< average of the particles' values in the cell
  sum    ///< sum (e.g. mass per cell; divide by the cell volume for a density)
};

/// Bins quantity[i] at positions[i] into the cells of `grid` (its n, spacing and origin are used;
/// its values are ignored): a particle at p falls in cell floor((p − origin) / spacing), and
/// particles outside the grid are skipped. nz = 1 bins in 2D using x and y only.
/// Throws InputError on mismatched sizes, non-finite positions or values, or an empty grid.
GridField bin_particles(std::span<const Vec3> positions, std::span<const double> quantity,
                        const GridField& grid, BinReduction reduction = BinReduction::mean);

}  // namespace shockfield::analysis
