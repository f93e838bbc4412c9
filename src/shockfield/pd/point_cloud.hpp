#pragma once
// A peridynamic body as a point cloud (Liu et al. 2025, §1): reference positions x and the volume V of
// each point, in 1, 2 or 3 dimensions. In fewer than three dimensions the unused coordinates are
// zero and "volume" is a length (1D: per unit cross-section area) or an area (2D: per unit
// thickness), so stresses keep their units of Pa.
#include <array>
#include <filesystem>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield::pd {

struct PointCloud {
  int dim = 3;               ///< 1, 2 or 3
  double spacing = 0.0;      ///< lattice spacing ΔX [m] (the partial-volume correction needs it)
  std::vector<Vec3> x;       ///< reference positions [m]
  std::vector<double> volume;  ///< V [m^dim]

  std::size_t size() const { return x.size(); }
  /// Bounding box of the reference positions.
  std::pair<Vec3, Vec3> bounds() const;
};

/// Simple-cubic lattice of counts[0] × counts[1] × counts[2] points (counts beyond `dim` must be
/// 1) with spacing ΔX starting at `origin`, each point of volume ΔX^dim. Points are numbered x
/// fastest.
PointCloud lattice_cloud(int dim, const std::array<int, 3>& counts, double spacing,
                         const Vec3& origin = Vec3::Zero());

/// Reads "x y z volume" lines ('#' comments, blank lines skipped) for a `dim`-dimensional body
/// with nominal spacing ΔX. InputError naming the file and line on bad input.
PointCloud read_cloud(const std::filesystem::path& file, int dim, double spacing);

}  // namespace shockfield::pd
