#pragma once
// Samples for the paper's MPM studies (Xu et al. 2015, §4.1-4.2): solid blocks, porous bodies with
// random non-overlapping circular (2D) or spherical (3D) voids at a target porosity
// Δ = 1 − ρ/ρ0, a single cavity at a given depth, and the two loadings: symmetric impact of two
// bodies at ±v and impact on a rigid wall. The shock axis is the last one (y in 2D, z in 3D, as in
// the paper); the lateral axes are periodic.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/particles.hpp"

namespace shockfield::mpm {

/// A box filled with points on a regular lattice (one point per spacing^dim, at lattice-cell
/// centres), all at the same velocity.
struct Body {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  double spacing = 0.0;           ///< particle spacing [m]
  Vec3 velocity = Vec3::Zero();   ///< [m/s]
  int material = 0;               ///< index into the simulation's materials
  int id = 0;                     ///< contact body of its points (Particles::body)
};

struct Void {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};

struct VoidSpec {
  double porosity = 0.0;       ///< target Δ = 1 − ρ/ρ0 of the body, in (0, 1)
  double mean_radius = 0.0;    ///< r [m]
  double radius_spread = 0.0;  ///< radii uniform in r(1 ± spread), spread in [0, 1)
  std::uint64_t seed = 1;
  bool cross_periodic_sides = true;  ///< voids may cross the sides place_voids is told are periodic
};

/// Axes along which a body fills a periodic grid: the body's sides there are periodic images of
/// each other, not free faces.
using PeriodicAxes = std::array<bool, 3>;

/// What add_body did; porosity() is the achieved Δ = 1 − added/lattice_points.
struct BodyStats {
  std::size_t lattice_points = 0;
  std::size_t added = 0;
  double porosity() const { return 1.0 - static_cast<double>(added) / static_cast<double>(lattice_points); }
};

/// Add the lattice points of `body` that lie outside every void. InputError on a bad box/spacing.
BodyStats add_body(Particles& p, int dim, const Body& body, const materials::SolidMaterial& mat,
                   const std::vector<Void>& voids = {});

/// Random sequential placement of non-overlapping voids until their volume reaches porosity × body
/// volume. Along the axes of `periodic` (when spec.cross_periodic_sides) a void centre is uniform
/// over the whole period and a void may cross the side: the list then also holds its wrapped
/// images (after the placed voids), and overlaps are checked against every image, so the void
/// fraction is uniform up to the sides and the porosity counts each void once. Along the other
/// axes each void lies wholly inside the body. InputError with the reason when that is impossible
/// (porosity beyond the random-packing limit, voids larger than the body, placement jammed).
std::vector<Void> place_voids(int dim, const Body& body, const VoidSpec& spec, const PeriodicAxes& periodic = {});

/// One void of `radius` centred laterally in `body`, at `depth` above its low face along the shock
/// axis (the paper's z of §4.2.2).
Void cavity_at(int dim, const Body& body, double depth, double radius);

/// Grid covering [lo, hi] with cubic cells of size h: lateral axes periodic (lo..hi must span a
/// whole number of cells), shock axis bounded with `low_face` at lo (Wall::Stick or Wall::Slip for
/// a rigid wall) and a free high face.
GridSpec impact_grid(int dim, const Vec3& lo, const Vec3& hi, double h, Wall low_face = Wall::Free);

/// Symmetric impact: `lower` moving at +speed along the shock axis and its copy stacked on top
/// moving at −speed, meeting at lower.hi; the copy is contact body lower.id + 1. Returns the stats of the two bodies.
std::vector<BodyStats> add_symmetric_impact(Particles& p, int dim, const Body& lower, double speed,
                                            const materials::SolidMaterial& mat);

}  // namespace shockfield::mpm
