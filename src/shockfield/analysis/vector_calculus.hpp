#pragma once
// Rotation (curl) and divergence of a vector field given as component grids (Xu et al. 2015, §3.1:
// fields may be velocity components), by second-order central differences; at the faces of an
// open grid, first-order one-sided differences. A result cell is void when a cell it uses is void.
#include <array>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// ∇·v from 2 (2D) or 3 (3D) components on the same grid.
GridField divergence(const GridField& vx, const GridField& vy, const GridField* vz,
                     bool periodic);
/// ∂v_y/∂x − ∂v_x/∂y of a 2D field.
GridField curl_2d(const GridField& vx, const GridField& vy, bool periodic);
/// ∇×v of a 3D field: its x, y, z components.
std::array<GridField, 3> curl_3d(const GridField& vx, const GridField& vy, const GridField& vz,
                                 bool periodic);

}  // namespace shockfield::analysis
