#pragma once
// Local configurations of a thresholded grid field (Xu et al. 2015, §3.1: "it can be calculated in a local
// way via the additivity relation"). Every Minkowski functional of {Θ ≥ Θ_th} on the lattice is a
// sum over all 2×2 (2D) or 2×2×2 (3D) blocks of cells of a weight that depends only on which cells
// of the block are white (its configuration, one of 16 or 256). Bit b of a configuration is block
// cell (dx, dy, dz) with b = dx + 2 dy + 4 dz; a set bit means white (Θ ≥ Θ_th).
//
// The weights are integer vectors (white cells, 2^D χ, crossings per direction class, ... — see
// minkowski.cpp), so the per-threshold sums over blocks are exact integers: the one-pass route
// equals the one-threshold route bit for bit, for any number of threads.
#include <cstdint>
#include <span>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// What lies beyond the grid's faces.
enum class Boundary {
  open,  ///< black cells (Θ = −∞) all around: white regions touching a face are closed by it
         ///< (scikit-image's convention); n + 1 blocks per axis
  periodic  ///< the grid wraps around (a torus): the surrounding region is not counted; n blocks
};

/// Number of block configurations in `dimension` (2 or 3): 16 or 256.
constexpr std::size_t configurations(int dimension) {
  return dimension == 3 ? 256 : 16;
}

/// An integer weight vector of `width` entries per block configuration: row c of `values` is the
/// weight of configuration c. Entries must lie within ±2^15 (a one-hot table counts the
/// configurations themselves).
struct BlockWeights {
  int dimension = 2;
  std::size_t width = 0;
  std::vector<std::int32_t> values;  ///< configurations(dimension) rows of width
};

/// Sums over all blocks of the weight of each block's configuration, one row per threshold.
struct BlockSums {
  std::vector<double> thresholds;
  std::size_t width = 0;
  std::vector<std::int64_t> sums;  ///< thresholds.size() rows of width

  std::span<const std::int64_t> row(std::size_t k) const {
    return {sums.data() + k * width, width};
  }
};

/// Throws InputError unless the thresholds are finite, strictly increasing and at most 65535.
void require_increasing(std::span<const double> thresholds);

/// Reference route, one threshold: binarises the field at `threshold` and adds the weight of
/// every block's configuration directly.
BlockSums sum_block_weights(const GridFieldView& field, double threshold, Boundary boundary,
                            const BlockWeights& weights);

/// All thresholds in one pass over the field. Each cell gets its level K = number of thresholds
/// <= Θ (the cell is white exactly for thresholds k < K); a block's configuration then changes only
/// at its cells' levels, so each block adds w(new) − w(old) to a difference table at those few
/// levels (a table of (thresholds + 1) × width integers per thread, small enough for L1), and a
/// prefix sum over thresholds gives the sums.
BlockSums sum_block_weights(const GridFieldView& field, std::span<const double> thresholds,
                            Boundary boundary, const BlockWeights& weights);

/// Number of blocks the field has under `boundary`.
std::int64_t block_count(const GridFieldView& field, Boundary boundary);

}  // namespace shockfield::analysis
