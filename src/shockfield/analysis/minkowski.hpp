#pragma once
// Minkowski functionals of the white set {Θ ≥ Θ_th} of a grid field (Xu et al. 2015, §3.1, eqs. 32–33;
// used in §4.1.2, Figs. 32–45), for every threshold from one pass over the field.
//
// Estimators (docs/analysis-minkowski.md):
//  - area / volume: white cells × cell size (exact on the lattice);
//  - boundary length (2D) and surface area (3D): Crofton's formula on the lattice lines through
//    the cells, L = (π/2) E_θ[crossings / line density] with the 4 directions 0°, 45°, 90°, 135°
//    (equal weights), S = 2 E_u[…] with the 13 directions of the 3×3×3 neighbourhood weighted by
//    their spherical Voronoi areas (Legland, Kiêu & Devaux, Image Anal. Stereol. 26 (2007) 83);
//    unbiased over orientations, so it converges to 2πr and 4πr² for digitised disks and balls
//    (the count of cell edges, the "pixel perimeter", converges to 8r, 4/π too long);
//  - Euler characteristic: exact, from the vertices, edges, faces (and cubes) of the cell
//    complex of the chosen connectivity (a white cell is a closed square/cube for 8 / 26, a point
//    joined to its 4 / 6 neighbours for 4 / 6);
//  - mean breadth b̄ (3D) = E_u[Σ_planes χ(section) × plane spacing], Crofton's formula for
//    planes over the same 13 directions; integral mean curvature M = 2π b̄.
#include <cstdint>
#include <span>
#include <vector>

#include "shockfield/analysis/block_configurations.hpp"
#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

/// 2D connectivity of the white set; black uses the other one (4 ↔ 8).
enum class Connectivity2D { four = 4, eight = 8 };
/// 3D adjacency pair (white, black).
enum class Adjacency3D { six_26 = 6, twentysix_6 = 26 };

struct MinkowskiOptions {
  Boundary boundary = Boundary::periodic;
  Connectivity2D connectivity2d = Connectivity2D::eight;
  Adjacency3D adjacency3d = Adjacency3D::twentysix_6;
};

struct Functionals2D {
  double threshold = 0.0;
  double area_fraction = 0.0;         ///< A: white cells / all cells
  double boundary_length = 0.0;       ///< L, in length units (grid spacing h = 1 → cells)
  std::int64_t euler = 0;             ///< χ = N_W − N_B, eq. (32)
  double euler_per_black_node = 0.0;  ///< χ = (N_W − N_B) / N, eq. (33); NaN if N = 0
  std::int64_t white_cells = 0;
};

struct Functionals3D {
  double threshold = 0.0;
  double volume_fraction = 0.0;          ///< V: white cells / all cells
  double surface_area = 0.0;             ///< S, in length units squared
  double mean_breadth = 0.0;             ///< b̄, in length units
  double integral_mean_curvature = 0.0;  ///< M = 2π b̄
  std::int64_t euler = 0;                ///< χ = components − tunnels + cavities
  double euler_per_black_node = 0.0;     ///< χ / N as in eq. (33); NaN if N = 0
  std::int64_t white_cells = 0;
};

/// The integer block weights the functionals are computed from (dimension 2 or 3): white cells,
/// 2^D χ for both connectivities, lattice-line crossings per direction class and (3D) the
/// Euler characteristics of the mean breadth's planar sections.
const BlockWeights& minkowski_weights(int dimension);

/// Functionals of threshold row k of `sums` (of minkowski_weights), for `field`'s grid (cell
/// count and spacing).
Functionals2D functionals_2d(const BlockSums& sums, std::size_t k, const GridFieldView& field,
                             Connectivity2D connectivity);
Functionals3D functionals_3d(const BlockSums& sums, std::size_t k, const GridFieldView& field,
                             Adjacency3D adjacency);

/// All thresholds (strictly increasing) in one pass. Throws InputError on a bad field, bad
/// thresholds, a grid of the wrong dimension or unequal spacings.
std::vector<Functionals2D> minkowski_2d(const GridFieldView& field, std::span<const double> thresholds,
                                        const MinkowskiOptions& options = {});
std::vector<Functionals3D> minkowski_3d(const GridFieldView& field, std::span<const double> thresholds,
                                        const MinkowskiOptions& options = {});

/// `count` thresholds evenly spaced over the range of the fields' non-void values (all the
/// frames of a run together: the first frame of a shock run is often uniform).
std::vector<double> linear_thresholds(std::span<const GridFieldView> fields, std::size_t count);
std::vector<double> linear_thresholds(const GridFieldView& field, std::size_t count);

}  // namespace shockfield::analysis
