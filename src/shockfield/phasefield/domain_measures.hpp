#pragma once
// Shape of the hcp set {ξ > 1/2} of a phase field, for series.csv (docs/phasefield.md "Domain
// measures"):
// - its surface: the Minkowski functionals of analysis/minkowski (Crofton estimators; boundary
//   length in 2D, surface area and integral mean curvature M in 3D; on a periodic grid the set
//   wraps, with any wall every face of the grid closes it), the Euler characteristic χ (number of domains less holes) and the mean
//   curvature of the surface, M/S in 3D and, by Gauss–Bonnet, 2πχ/L in 2D; in 1D the number of
//   fronts (crossings of 1/2);
// - its principal axes, from the central second moments of the nodes with ξ > 1/2 (Xu et al.
//   2015 §4.4.2, the central-moment method of the hcp domains; moments of ξ itself would be
//   widened by the diffuse interface): a uniform solid
//   ellipsoid of semi-axes a ≥ b ≥ c has moments a²/5, b²/5, c²/5 (an ellipse a²/4, b²/4), so the
//   semi-axes are √(5λ) (√(4λ) in 2D, √(3λ) in 1D) of the eigenvalues λ. The centre along a
//   periodic axis is the circular mean, and distances are minimum-image about it: right for one
//   domain (even across a periodic face), an average over the domains otherwise.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/phasefield/grid.hpp"

namespace shockfield::phasefield {

struct DomainMeasures {
  double surface = 0.0;         ///< fronts (1D), boundary length (2D), surface area (3D)
  double mean_curvature = 0.0;  ///< 2πχ/L (2D), M/S (3D); 0 without a surface or in 1D
  std::int64_t euler = 0;       ///< χ of the hcp set (2D/3D); fronts/2 in 1D
  std::array<double, 3> semi_axes{0, 0, 0};  ///< a ≥ b ≥ c (unused dimensions 0)
  std::array<double, 3> long_axis{0, 0, 0};  ///< unit vector along a
  std::array<double, 3> center{0, 0, 0};
};

DomainMeasures domain_measures(const Grid& grid, const std::vector<double>& xi);

}  // namespace shockfield::phasefield
