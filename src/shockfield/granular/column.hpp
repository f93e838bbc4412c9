#pragma once
// A 2D column of spheres with Hertz contacts under gravity, in a box with rigid flat walls (left,
// right, floor), built on the MD engine's pieces rather than a second copy of them: the spheres
// are md::Atoms (positions, velocities, forces, per-type mass; here in SI units, m, m/s, N, kg),
// the contacts come from geometry::build_neighbor_list's half list and are summed by
// md::potentials::accumulate_pair_forces (the threaded, race-free pair loop every MD potential
// uses) with a Hertz kernel. What is granular is the kernel, the walls, gravity and the
// integrator (velocity Verlet, as LAMMPS fix nve):
//   pair   F = κ_ij δ^{3/2}, δ = R_i + R_j − r, κ_ij = (4/3) E* √R* (contact_law.hpp, Johnson 1985
//          eqs. 4.22–4.23), no tension, no damping, no tangential force;
//   walls  F = κ_w δ^{3/2}, δ = R − (distance to the wall), κ_w with E₂ = ∞, R₂ = ∞;
//   gravity −m g along y. All spheres lie in z = 0 and no force has a z component, so the column
//   stays exactly 2D.
// The neighbour list (cutoff max(R_i + R_j) + skin) is rebuilt when a sphere has moved more than
// half the skin since the last build (LAMMPS neigh_modify check yes). Docs: docs/granular.md
// ("The 2D column of spheres"); peer test against LAMMPS gran/hertz/history:
// tests/unit/granular/column_test.cpp.
#include <vector>

#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::granular {

/// One kind of sphere (md::Atoms type), SI units.
struct SphereType {
  double radius = 1e-3;           ///< R [m]
  double density = 7850.0;        ///< ρ [kg/m³]; m = (4/3)πR³ρ
  double youngs_modulus = 200e9;  ///< E [Pa]
  double poisson_ratio = 0.3;     ///< ν
};

struct ColumnSpec {
  std::vector<SphereType> types;
  double left = 0.0;     ///< x of the left wall [m]
  double right = 0.0;    ///< x of the right wall [m]
  double floor = 0.0;    ///< y of the floor [m]
  double gravity = 9.81; ///< g toward −y [m/s²]
  double skin = 0.0;     ///< neighbour-list skin [m]; 0: a tenth of the smallest radius
  double time_step = 0.0;  ///< [s]
};

class Column {
 public:
  /// `spheres` holds the owned spheres (types 0..types−1, z = 0, no ghosts); its masses are set
  /// from the types. InputError for a sphere outside the box or types that make no sphere.
  Column(ColumnSpec spec, md::Atoms spheres);

  void step();
  double time() const { return time_; }
  long long step_count() const { return steps_; }
  const md::Atoms& spheres() const { return atoms_; }
  /// Kinetic + contact + wall + gravitational energy (gravity from y = floor) [J].
  double total_energy() const;
  long long neighbor_builds() const { return builds_; }

 private:
  void build_list();
  void compute_forces();

  ColumnSpec spec_;
  md::Atoms atoms_;
  std::vector<double> pair_kappa_, pair_contact_, wall_kappa_, radius_;  ///< per type pair / type
  geometry::NeighborList list_;
  md::potentials::ThreadScratch scratch_;
  std::vector<Vec3> built_at_;
  double contact_energy_ = 0.0;
  double time_ = 0.0;
  long long steps_ = 0, builds_ = 0;
};

}  // namespace shockfield::granular
