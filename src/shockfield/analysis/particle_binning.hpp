#pragma once
// Particles to field: a particle quantity (temperature, density, velocity component of MPM or MD
// particles) binned onto a regular grid so the grid analyses apply. Cells that receive no
// particle are marked void (no material: a pore, a free surface, a gap).
#include <span>
#include <string>
#include <vector>

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

/// The scalar point array `array` of each particle frame in `files` (.vtp, .pvtp:
/// analysis/point_frame_reader) binned by bin_particles (mean per cell) on one grid of cubic cells
/// of side `cell` covering the particles of every frame: its origin the lowest coordinate over all
/// frames, floor((max − min) / cell) + 1 cells per axis, nz = 1 when every particle has the same z
/// (a 2D model). Each field carries the array's units and the points' as its length_units.
/// Throws InputError for a cell that is not positive and finite or a grid of more than 1e8 cells.
std::vector<GridField> bin_point_frames(const std::vector<std::string>& files, const std::string& array, double cell);

}  // namespace shockfield::analysis
