#pragma once
// `method = "pd"` with a [homogeneous] table: one material point of the crystal law whose N_g
// grains (the [material] orientation keys with taylor_grains) all follow the isochoric
// compression of Liu et al. (2025) eq. 44 (Taylor assumption), the simple-compression test of Liu et al. (2025)
// §4.1 / Fig. 5 (annealed OFHC copper, Table 1, 50 random orientations). No lattice, no waves: the
// same [material] as a shock run, driven homogeneously. Keys and outputs: docs/pd.md.
#include <memory>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/materials/strength/crystal_compression.hpp"

namespace shockfield::pd {

/// Reads [homogeneous]: strain_rate, end_strain, strain_increment, output_increment.
struct HomogeneousSpec {
  materials::CompressionPath path;
  double output_increment = 0.01;  ///< |Δε| between output rows
};
HomogeneousSpec read_homogeneous(const Config& t);

/// The run driver's plug-in for a case whose root has [homogeneous] (pd::make_method sends it here).
std::unique_ptr<Method> make_homogeneous_method(const Config& root, const RunOptions& options);

}  // namespace shockfield::pd
