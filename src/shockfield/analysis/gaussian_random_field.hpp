#pragma once
// Gaussian random fields on a periodic grid, the reference for Minkowski functionals: their mean
// values against the threshold are known in closed form (Adler 1981; Tomita 1986), see
// docs/analysis-minkowski.md. Used by tests, benchmarks and examples.
#include <cstdint>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

struct GaussianRandomField {
  GridField field;        ///< zero mean, unit variance (in expectation)
  double lambda = 0.0;    ///< second spectral moment ⟨(∂_x Θ)²⟩ / σ² of the grid spectrum
};

/// A periodic Gaussian field with covariance ≈ exp(−r² / (2 ℓ²)) (power spectrum
/// ∝ exp(−k² ℓ² / 2)), unit grid spacing, ℓ = `correlation_length` cells; nz = 1 gives 2D.
/// Deterministic for a given seed.
GaussianRandomField gaussian_random_field(std::size_t nx, std::size_t ny, std::size_t nz,
                                          double correlation_length, std::uint64_t seed);

}  // namespace shockfield::analysis
