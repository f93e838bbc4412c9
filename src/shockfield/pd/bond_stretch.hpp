#pragma once
// One point's bonds measured at the current positions, staged in contiguous arrays so that the
// square roots and divisions of a whole family run as packed SIMD instructions (the gathers of
// y_j stay scalar, in a loop of their own). The bond loops (bond_force.cpp) read these arrays in
// the family's order. Every value is what per-bond scalar code computes, bit for bit (the same
// operations in the same order; packed sqrt and division are IEEE correctly rounded):
//   Y = y_j − y_i,  r = |Y| = √((Y_x² + Y_y²) + Y_z²) (Eigen's norm()),  e = r − r0 (0 when
//   |e| < 2.2204e-16, LAMMPS's NEAR_ZERO in pair_peri_*.cpp),  s = e / r0 (the exact division:
//   critical-stretch damage compares it),
// and the pull t·V_j·β/r of the bond force (PMB: (k_b·s)/r, bond_models.hpp).
#include <cstddef>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/pd/family.hpp"

namespace shockfield::pd {

inline constexpr double kNearZeroExtension = 2.2204e-16;

struct BondStretches {
  std::vector<double> dx, dy, dz;  ///< Y = y_j − y_i
  std::vector<double> r;           ///< |Y|
  std::vector<double> extension;   ///< e
  std::vector<double> stretch;     ///< s = e / r0
  std::vector<double> pull;        ///< the caller's t·V_j·β, then t·V_j·β/r (0 at r = 0)

  /// Measures the bonds of point i (every bond, intact or not).
  void measure(const Family& family, std::size_t i, const std::vector<Vec3>& y);
  /// pull[k] /= r[k] (0 where r = 0) for the first `count` bonds measured last.
  void divide_pull_by_length(std::size_t count);
};

}  // namespace shockfield::pd
