#pragma once
// The MD simulation: owns the atoms, box, potential, neighbour list and fixes, and runs the
// velocity-Verlet time loop (LAMMPS metal units). Neighbour lists are rebuilt when an atom moved
// more than half the skin since the last build (LAMMPS `neigh_modify every 1 delay 0 check yes`).
#include <functional>
#include <memory>
#include <vector>

#include "shockfield/geometry/box.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/fix.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md {

class Decomposition;  // md/decomposition.hpp

struct ThermoState {
  double temperature = 0;  ///< K, 3N−3 degrees of freedom (LAMMPS compute temp)
  double kinetic = 0;      ///< eV
  double potential = 0;    ///< eV
  double pressure = 0;     ///< bar
  Voigt6 pressure_tensor = Voigt6::Zero();  ///< bar, xx yy zz xy xz yz
  double volume = 0;       ///< Å³
};

class Simulation {
 public:
  Simulation(geometry::Box box, Atoms atoms, std::unique_ptr<Potential> potential, double timestep,
             double skin);

  // State (public: fixes and diagnostics work on it directly).
  geometry::Box box;
  Atoms atoms;
  std::unique_ptr<Potential> potential;
  geometry::NeighborList list;
  ForceResult forces;
  double dt;              ///< ps
  double skin;            ///< Å
  /// Å, the pad of shrink-wrapped faces: 1e-4 × the box length the simulation was created with
  /// (LAMMPS Domain::small, set by create_box / read_data and kept while the box changes).
  Vec3 shrink_margin;
  std::int64_t step = 0;
  double time = 0;        ///< ps, step·dt (set by advance)
  std::vector<std::unique_ptr<Fix>> fixes;
  /// The rank grid of a decomposed run (md/decomposition.hpp); null on one rank. With it, `atoms`
  /// are this rank's, and every step (and thermo) is collective.
  std::shared_ptr<Decomposition> domain;
  bool per_atom_this_step = false;  ///< set by diagnostics that need per-atom energy/virial
  std::int64_t rebuilds = 0;
  /// Neighbour-list policy (LAMMPS `neigh_modify every N delay D check yes|no`): a rebuild is
  /// considered when at least `neighbor_delay` steps passed since the last one and that count is
  /// a multiple of `neighbor_every`; it happens if `neighbor_check` is off or an atom moved more
  /// than half the skin (or a box face by as much).
  int neighbor_every = 1;
  int neighbor_delay = 0;
  bool neighbor_check = true;
  std::int64_t steps_since_rebuild = 0;
  /// Wall seconds of the step phases (the run's performance summary, LAMMPS's Pair/Neigh/Comm):
  /// force evaluation, neighbour-list rebuilds (with their ghosts), ghost position updates.
  double force_seconds = 0, neighbor_seconds = 0, ghost_seconds = 0;

  /// Wraps, rebuilds ghosts and list, and computes forces (per-atom tallies if asked).
  void setup(bool per_atom);
  /// Advances one velocity-Verlet step through all fix stages. `want_per_atom(step)` tells
  /// whether the forces of the new step need per-atom tallies.
  void advance(const std::function<bool(std::int64_t)>& want_per_atom);
  /// Forces on the current positions (rebuilding the list if needed).
  void compute_forces(bool per_atom);
  /// Rebuild ghosts and neighbour list now (after changing positions or the box by hand).
  void rebuild();
  /// Replaces the cell by the flipped, equivalent one (geometry::CellFlip; LAMMPS's pre_exchange
  /// flip): image counts follow, and the next force evaluation wraps the atoms into the new cell
  /// and rebuilds ghosts and the neighbour list. Between initial_integrate and the forces only.
  void flip_cell(const geometry::CellFlip& flip);

  double kinetic_energy() const;
  ThermoState thermo() const;
  /// Positions and box at the last rebuild (the restart reproduces the list from them).
  const std::vector<Vec3>& positions_at_rebuild() const { return x_rebuild_; }
  const geometry::Box& box_at_rebuild() const { return box_rebuild_; }
  /// Sets the rebuild reference without rebuilding: a copy of a decomposed run gathered on one
  /// rank to be written as the serial checkpoint (`x_rebuild` per owned atom).
  void set_rebuild_reference(std::vector<Vec3> x_rebuild, const geometry::Box& box_rebuild) {
    x_rebuild_ = std::move(x_rebuild);
    box_rebuild_ = box_rebuild;
  }
  /// Restores a rebuild reference from a checkpoint and rebuilds ghosts and list from it.
  void restore_rebuild_state(const std::vector<Vec3>& x_rebuild, const geometry::Box& box_rebuild);

  /// Throws RunError with a diagnosis if positions/velocities/forces/energy are not finite, an
  /// atom left a fixed boundary, or an atom drifted more than half the skin in the last step.
  void check_health() const;

 private:
  bool needs_rebuild() const;
  bool needs_rebuild_here() const;
  // Σ over every rank's atoms in rank order (the local sums on one rank).
  std::vector<double> over_ranks(std::vector<double> partials) const;
  void shrink_wrap();
  std::vector<Vec3> x_rebuild_;
  geometry::Box box_rebuild_;
  double max_drift_ = 0;  ///< largest drift of the last step, Å
};

}  // namespace shockfield::md
