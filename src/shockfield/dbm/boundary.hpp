#pragma once
// Boundary conditions of the DBM, applied by filling the two ghost layers of f before each
// Runge–Kutta stage: periodic, outflow (zero gradient), inflow (f^eq of a fixed state),
// reflecting (specular: mirrored velocities) and wall (moving isothermal wall: ghost macroscopic
// state mirrored about the wall values, non-equilibrium part copied from the fluid).
#include <array>
#include <string>
#include <vector>

#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

enum class BoundaryKind { periodic, outflow, inflow, reflecting, wall };

struct BoundarySide {
  BoundaryKind kind = BoundaryKind::periodic;
  Macro state;  // inflow state, or the wall's velocity and temperature (rho unused)
};

/// Sides in the order x-low, x-high, y-low, y-high.
struct Boundaries {
  std::array<BoundarySide, 4> side;
  /// InputError when periodic is not paired on an axis.
  void check() const;
};

BoundaryKind boundary_kind(const std::string& name);  // InputError on an unknown name

/// Fills the ghost layers of f (Q arrays of lattice.cells()).
class GhostFiller {
 public:
  GhostFiller(const VelocityModel& model, const MomentInversion& inversion, double b,
              const Lattice& lattice, const Boundaries& boundaries);
  void fill(std::vector<double>& f) const;

 private:
  // Ghost cell g takes its value from interior cell s of the same row/column (mirror index).
  void fill_side(std::vector<double>& f, int side) const;
  Macro moments_at(const std::vector<double>& f, std::size_t cell) const;

  const VelocityModel& model_;
  const MomentInversion& inversion_;
  double b_;
  Lattice lattice_;
  Boundaries boundaries_;
  std::array<std::vector<int>, 2> mirror_;
};

}  // namespace shockfield::dbm
