#pragma once
// Simple compression of a crystal aggregate under the Taylor assumption (Liu et al. 2025, §4.1, Fig. 5):
// every grain follows the same isochoric deformation gradient of eq. 44 and the aggregate's
// stress is their volume average (eq. 43). This is the material-point test the paper holds the
// crystal law of Table 1 against (annealed OFHC copper, Kalidindi, Bronkhorst & Anand 1992).
#include <functional>
#include <vector>

#include "shockfield/materials/strength/crystal_taylor.hpp"

namespace shockfield::materials {

/// Eq. 44: F = diag(e^(−ε/2), e^(−ε/2), e^ε), det F = 1, along `axis` (the paper's 3 is z = 2; the
/// pd driver loads along x = 0 like every pd run); compression for ε < 0.
Mat3 isochoric_compression(double strain, int axis = 2);

/// Eq. 45: the axial stress of a test whose lateral faces are free, read from the deviator s of
/// σ as s33 − ½(s11 + s22) = σ33 − ½(σ11 + σ22) for axis 3 (the paper prints the ½ as
/// 1/(2(s11 + s22)), a typesetting slip: the expression must be linear in the stress).
double axial_stress(const Mat3& sigma, int axis = 2);

struct CompressionPath {
  double strain_rate = -0.01;        ///< ε̇ [1/s]; eq. 44 has ε = −0.01·t
  double end_strain = -1.0;          ///< last ε, same sign as ε̇
  double strain_increment = 1e-4;    ///< |Δε| per step (the law sub-steps inside, Algorithm 1)
  long long steps() const;
};

/// Per step: step number k (0 before the first), time, ε, the grains' state and σ^g, and ⟨σ⟩
/// (eq. 43).
using CompressionObserver =
    std::function<void(long long k, double time, double strain, const TaylorAggregate::State& state,
                       const std::vector<Mat3>& grain_stress, const Mat3& average)>;

/// Drives every grain of `aggregate` along eq. 44 (loading `axis`) from ε = 0 to
/// path.end_strain (grains in parallel with OpenMP; the result does not depend on the thread
/// count) and calls `observe` at ε = 0 and after every step. Returns the grains' final state.
TaylorAggregate::State compress_aggregate(const TaylorAggregate& aggregate, const CompressionPath& path,
                                          const CompressionObserver& observe, int axis = 2);

}  // namespace shockfield::materials
