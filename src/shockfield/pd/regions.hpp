#pragma once
// Loading regions of a pd case (`[[region]]`, docs/pd.md): a box, sphere or cylinder of the
// reference configuration (geometry/region.hpp, LAMMPS's `region` shapes) whose points start with
// a given velocity, or are held at a prescribed velocity for all time (a boundary condition: an
// impactor's face, a loading platen, the Kalthoff–Winkler projectile modelled as a prescribed
// velocity on the struck edge).
//
// A held point keeps v = v_p: after every force evaluation its force density is set to zero, so
// both velocity-Verlet half kicks leave v_p unchanged and its position advances by Δt·v_p each
// step, y = x + v_p·t. The force the body exerts on it is the reaction of the boundary, which the
// total momentum of the body then follows (dP/dt = −Σ_held V_i L_i).
//
// A `separate` region is a body of its own (an impactor, a projectile): the bonds between its points
// and the points outside it are left out of every family, so it touches the rest only through the
// short-range contact force of the bond models (contact.hpp). Separate regions must not overlap.
#include <array>
#include <cstddef>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/types.hpp"
#include "shockfield/geometry/region.hpp"
#include "shockfield/pd/point_cloud.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

struct LoadRegion {
  geometry::Region shape;
  Vec3 velocity = Vec3::Zero();  ///< [m/s] (components beyond the body's dimension are 0)
  bool prescribed = false;       ///< held at `velocity` every step; else the initial velocity
  bool sets_velocity = true;     ///< false: a separate body keeping the velocity it has
  bool separate = false;         ///< a body of its own: no bonds to the points outside
};

/// Reads one [[region]] table: the shape keys of geometry::region_from_config, `separate`, and
/// exactly one of `velocity` or `prescribed_velocity` (`dim` numbers; neither for a separate body
/// at rest). Refused with its `shape` key when it selects no point of the lattice of `counts`
/// points `spacing` apart from the origin (counted without building the body).
LoadRegion read_load_region(const Config& t, int dim, const std::array<int, 3>& counts, double spacing);

/// Refuses (under `separate` of the later table) two separate regions that share a lattice point.
void check_bodies_apart(const std::vector<Config>& tables, const std::vector<LoadRegion>& regions,
                        const std::array<int, 3>& counts, double spacing);

/// Per bond of the family: 1 when it joins two different bodies (a separate region and the rest,
/// or two separate regions).
std::vector<unsigned char> bonds_between_bodies(const PointCloud& cloud, const Family& family,
                                                const std::vector<LoadRegion>& regions);

/// The points of the cloud a region selects, in index order.
std::vector<std::size_t> points_in(const geometry::Region& region, const PointCloud& cloud);

/// Gives the regions' points their velocities (tables in order, a later one winning; a prescribed
/// velocity wins over an initial one) when `initial`, and holds the prescribed points from now on
/// (an after_force hook of the simulation; call before its first step or setup, and again on
/// resume with `initial` false).
void apply_regions(Simulation& sim, const std::vector<LoadRegion>& regions, bool initial);

}  // namespace shockfield::pd
