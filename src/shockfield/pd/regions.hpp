#pragma once
// Loading regions of a pd case (`[[region]]`, docs/pd.md): a box, sphere or cylinder of the
// reference configuration (geometry/region.hpp, LAMMPS's `region` shapes) whose points start with
// a velocity (one for all, a formula of x, y, z, or one per point from a file), or are held at a
// prescribed velocity or displacement for all time (a boundary condition: an impactor's face, a
// loading platen, the Kalthoff–Winkler projectile modelled as a prescribed velocity on the struck
// edge, a clamped or displaced bar end).
//
// A held point does not feel the body: after every force evaluation its force density is set to
// zero and its velocity to the prescribed one, so the velocity-Verlet half kicks leave it there.
// A prescribed velocity v_p moves it by Δt·v_p each step, y = x + v_p·t. A prescribed
// displacement u(t) = U·min(t/T, 1) (ramped linearly over `ramp_time` T, or held from t = 0 when
// T = 0) sets its position y = x + u(t_{n+1}) after each drift, before the forces are evaluated
// (exact at every step), and its velocity to u̇ = U/T while t < T, then 0. The force the body exerts
// on a held point is the reaction of the boundary, which the total momentum of the body then
// follows (dP/dt = −Σ_held V_i L_i). `components` holds only some components (a roller: x held,
// y free): the rest of the point's force, velocity and position evolve with the body, as LAMMPS's
// `fix setforce NULL 0.0 NULL` and `velocity set` with NULL components do.
//
// A `body_force` b [N/m³] is added to the force density of the region's points after every
// force evaluation, ρü = L + b (Liu et al. 2025, eq. 1), before held points drop theirs: a
// traction σ on an edge as b = σ/ΔX on its outer layer of points (the crack-branching plates of
// Ha & Bobaru 2010 and Bobaru & Zhang 2015 are loaded so).
//
// A `separate` region is a body of its own (an impactor, a projectile): the bonds between its
// points and the points outside it are left out of every family, so it touches the rest only
// through the short-range contact force of the bond models (contact.hpp). Separate regions must not
// overlap.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/expression.hpp"
#include "shockfield/core/types.hpp"
#include "shockfield/geometry/region.hpp"
#include "shockfield/pd/point_cloud.hpp"
#include "shockfield/pd/simulation.hpp"

namespace shockfield::pd {

/// What a region does to its points.
enum class Loading {
  none,                 ///< nothing (a separate body keeping the velocity it has)
  velocity,             ///< initial `velocity`
  velocity_formula,     ///< initial velocity from `velocity_formula`, one formula of x, y, z per
                        ///< component
  velocity_file,        ///< initial velocity per point from `velocity_file`
  prescribed_velocity,  ///< held at `prescribed_velocity`
  prescribed_displacement,  ///< held at `prescribed_displacement`, ramped over `ramp_time`
};

struct LoadRegion {
  LoadRegion() = default;
  LoadRegion(const geometry::Region& s, Loading l, const Vec3& v = Vec3::Zero(),
             bool is_separate = false)
      : shape(s), loading(l), velocity(v), separate(is_separate) {}

  geometry::Region shape;
  Loading loading = Loading::velocity;
  Vec3 velocity =
      Vec3::Zero();       ///< [m/s] velocity or prescribed_velocity (beyond the body's dimension 0)
  bool separate = false;  ///< a body of its own: no bonds to the points outside
  Vec3 displacement = Vec3::Zero();  ///< [m] prescribed_displacement U
  double ramp_time = 0.0;            ///< [s] T of u(t) = U·min(t/T, 1); 0: U from t = 0
  std::vector<Expression> formula;   ///< velocity_formula: one per dimension of the body
  std::vector<Vec3> point_velocity;  ///< velocity_file: one per selected point, in point order
  Vec3 body_force = Vec3::Zero();    ///< [N/m³] b added to the points' force density (any loading)
  /// Held components (`components`; all by default): the others of a held point are free.
  std::array<bool, 3> held_components{true, true, true};

  bool held() const {
    return loading == Loading::prescribed_velocity || loading == Loading::prescribed_displacement;
  }
  /// u(t) of a prescribed displacement.
  Vec3 displacement_at(double t) const {
    return ramp_time > 0.0 && t < ramp_time ? Vec3((t / ramp_time) * displacement) : displacement;
  }
  /// The velocity of a held point at t (u̇(t) for a prescribed displacement).
  Vec3 held_velocity(double t) const {
    if (loading == Loading::prescribed_velocity) return velocity;
    return ramp_time > 0.0 && t < ramp_time ? Vec3(displacement / ramp_time) : Vec3(Vec3::Zero());
  }
};

/// The reference points of the body as a case reader sees them before it is built: the points
/// of a cloud read from a file, or else the lattice of `counts` points `spacing` apart from
/// `origin` (numbered x fastest, as lattice_cloud does), walked in place.
struct BodyPoints {
  std::array<int, 3> counts{1, 1, 1};
  double spacing = 0.0;
  const PointCloud* cloud = nullptr;
  Vec3 origin = Vec3::Zero();  ///< the lattice's first point [m]
  /// The first point (in point order) that `selects` accepts, if any.
  template <class Selects>
  std::optional<Vec3> first(Selects selects) const {
    if (cloud) {
      for (const Vec3& x : cloud->x)
        if (selects(x)) return x;
      return std::nullopt;
    }
    for (int k = 0; k < counts[2]; ++k)
      for (int j = 0; j < counts[1]; ++j)
        for (int i = 0; i < counts[0]; ++i)
          if (const Vec3 x = origin + spacing * Vec3(i, j, k); selects(x)) return x;
    return std::nullopt;
  }
  /// Text of the body's extent for messages.
  std::string extent() const;
};

/// Reads one [[region]] table: the shape keys of geometry::region_from_config, `separate`, and
/// exactly one of `velocity`, `velocity_formula`, `velocity_file`, `prescribed_velocity` or
/// `prescribed_displacement` (with `ramp_time` and `components`); none for a separate body keeping
/// its velocity or a region with a `body_force`.
/// Refused with its `shape` key when it selects no point of the body; a formula that does not
/// compile or is not finite at a selected point, and a file that does not give the selected
/// points in order, with their keys.
LoadRegion read_load_region(const Config& t, int dim, const BodyPoints& body);

/// Refuses (under `separate` of the later table) two separate regions that share a point.
void check_bodies_apart(const std::vector<Config>& tables, const std::vector<LoadRegion>& regions,
                        const BodyPoints& body);

/// Per bond of the family: 1 when it joins two different bodies (a separate region and the rest,
/// two separate regions, or points of two different files: `part`, one index per point, or empty).
std::vector<unsigned char> bonds_between_bodies(const PointCloud& cloud, const Family& family,
                                                const std::vector<LoadRegion>& regions,
                                                const std::vector<int>& part = {});

/// The points of the cloud a region selects, in index order.
std::vector<std::size_t> points_in(const geometry::Region& region, const PointCloud& cloud);

/// Gives the regions' points their initial velocities (tables in order, a later one winning; a
/// held point wins over an initial velocity) when `initial`, and from now on adds the body forces
/// (summed where regions overlap) and holds the prescribed points (hooks of the simulation; call before its first step or setup, and again on resume with
/// `initial` false). The hooks keep their own copy of `regions` (a temporary list is fine).
void apply_regions(Simulation& sim, const std::vector<LoadRegion>& regions, bool initial);

/// A line of log.txt saying what region `r` does to its `count` points.
std::string describe(const LoadRegion& r, std::size_t count);

}  // namespace shockfield::pd
