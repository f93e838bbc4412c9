#pragma once
// Initial velocities of a region's points from a file (`velocity_file` of [[region]], docs/pd.md):
// CSV with the header `x,y,z,vx,vy,vz` and then one row per point the region selects, in point
// order (the body's numbering: x fastest on a lattice), '#' comments and blank lines skipped. The
// x, y, z of each row must be the point's reference position to within 1e-6 ΔX, so a file made
// for another body, region or ordering is refused instead of being applied to the wrong points.
#include <filesystem>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield::pd {

/// The velocities of `points` (the reference positions of the selected points, in order) of a
/// `dim`-dimensional body of spacing ΔX. InputError naming the file and line on bad input.
std::vector<Vec3> read_point_velocities(const std::filesystem::path& file, int dim,
                                        const std::vector<Vec3>& points, double spacing);

}  // namespace shockfield::pd
