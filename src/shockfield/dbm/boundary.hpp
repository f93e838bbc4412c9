#pragma once
// Boundary conditions of the DBM, applied by filling the two ghost layers of f before each
// Runge–Kutta stage: periodic, outflow (zero gradient), inflow (f^eq of a fixed state),
// subsonic_inflow (characteristic: f^eq of a state with the incoming Riemann invariant and the
// entropy of the fixed state and the outgoing invariant of the fluid, docs/theory/dbm.md),
// reflecting (specular: mirrored velocities) and wall (moving isothermal wall: ghost macroscopic
// state mirrored about the wall values, non-equilibrium part copied from the fluid).
#include <array>
#include <string>
#include <vector>

#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

enum class BoundaryKind { periodic, outflow, inflow, subsonic_inflow, reflecting, wall };

/// True for the sides through which gas of a given state enters (inflow, subsonic_inflow).
inline bool feeds_gas(BoundaryKind kind) {
  return kind == BoundaryKind::inflow || kind == BoundaryKind::subsonic_inflow;
}

struct BoundarySide {
  BoundaryKind kind = BoundaryKind::periodic;
  Macro state;  // inflow state, or the wall's velocity and temperature (rho unused)
};

/// The ghost state of a subsonic_inflow side (1D characteristics of the Euler equations along the
/// side's normal, ideal gas of ratio gamma): the entropy p/ρ^γ, the tangential velocity and the
/// incoming Riemann invariant u_n + 2c/(γ−1) of `imposed`, the outgoing invariant u_n − 2c/(γ−1)
/// of `interior` (the fluid cell next to the side). u_n is the velocity into the domain: +u_axis
/// on a low side, −u_axis on a high side.
Macro subsonic_inflow_state(const Macro& imposed, const Macro& interior, int axis, bool high,
                            double gamma);
/// InputError unless `state` enters through the side (u_n > 0) slower than sound (u_n < c).
void check_subsonic_inflow(const Macro& state, int axis, bool high, double gamma);

/// Sides in the order x-low, x-high, y-low, y-high.
struct Boundaries {
  std::array<BoundarySide, 4> side;
  /// InputError when periodic is not paired on an axis.
  void check() const;
};

BoundaryKind boundary_kind(const std::string& name);  // InputError on an unknown name
/// The names boundary_kind accepts, in BoundaryKind order.
const std::vector<std::string>& boundary_kind_names();

/// Fills the ghost layers of f (Q arrays of lattice.cells()).
class GhostFiller {
 public:
  GhostFiller(const VelocityModel& model, const MomentInversion& inversion, double b,
              const Lattice& lattice, const Boundaries& boundaries);
  void fill(std::vector<double>& f) const;
  /// Fills the ghosts of one side (x-low, x-high, y-low, y-high); x sides fill the interior rows,
  /// y sides every column including the x ghosts (corners), so x sides go first.
  void fill_side(std::vector<double>& f, int side) const;

 private:
  // Ghost cell g takes its value from interior cell s of the same row/column (mirror index).
  Macro moments_at(const std::vector<double>& f, std::size_t cell) const;

  const VelocityModel& model_;
  const MomentInversion& inversion_;
  double b_, gamma_;  // degrees of freedom b and γ = (b + 2)/b
  Lattice lattice_;
  Boundaries boundaries_;
  std::array<std::vector<int>, 2> mirror_;
};

}  // namespace shockfield::dbm
