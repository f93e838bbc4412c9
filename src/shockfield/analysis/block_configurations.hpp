#pragma once
// Local configurations of a thresholded grid field (seed 000 §3.1: "it can be calculated in a local
// way via the additivity relation"). Every Minkowski functional of {Θ ≥ Θ_th} on the lattice is a
// sum over all 2×2 (2D) or 2×2×2 (3D) blocks of cells of a weight that depends only on which cells
// of the block are white; so the counts of the 16 (2D) or 256 (3D) block configurations, one row
// per threshold, hold everything. Bit b of a configuration is block cell (dx, dy, dz) with
// b = dx + 2 dy + 4 dz; a set bit means white (Θ ≥ Θ_th).
#include <cstdint>
#include <span>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// What lies beyond the grid's faces.
enum class Boundary {
  open,     ///< black cells (Θ = −∞) all around: white regions touching a face are closed by it
            ///< (scikit-image's convention); n + 1 blocks per axis
  periodic  ///< the grid wraps around (a torus): the surrounding region is not counted; n blocks
};

struct ConfigurationCounts {
  int dimension = 2;
  std::vector<double> thresholds;
  std::vector<std::int64_t> counts;  ///< thresholds.size() rows of configurations() counts

  std::size_t configurations() const { return dimension == 3 ? 256 : 16; }
  std::span<const std::int64_t> row(std::size_t k) const {
    return {counts.data() + k * configurations(), configurations()};
  }
};

/// Throws InputError unless the thresholds are finite, strictly increasing and at most 65535.
void require_increasing(std::span<const double> thresholds);

/// Reference route, one threshold: binarises the field at `threshold` and counts the
/// configurations of every block directly.
ConfigurationCounts count_configurations(const GridField& field, double threshold,
                                         Boundary boundary);

/// All thresholds in one pass over the field. Each cell gets its level K = number of thresholds
/// <= Θ (the cell is white exactly for thresholds k < K); a block's configuration then changes only
/// at its cells' levels, so each block adds ±1 to a difference table at those few levels, and a
/// prefix sum over thresholds gives the counts. Integer counts: equal bit for bit to calling the
/// one-threshold route per threshold, for any number of threads.
ConfigurationCounts count_configurations(const GridField& field,
                                         std::span<const double> thresholds, Boundary boundary);

/// Number of blocks the field has under `boundary` (every row of counts sums to it).
std::int64_t block_count(const GridField& field, Boundary boundary);

}  // namespace shockfield::analysis
