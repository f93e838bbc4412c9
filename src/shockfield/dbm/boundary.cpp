#include "shockfield/dbm/boundary.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {

void Boundaries::check() const {
  for (int axis = 0; axis < 2; ++axis) {
    const bool lo = side[2 * axis].kind == BoundaryKind::periodic;
    const bool hi = side[2 * axis + 1].kind == BoundaryKind::periodic;
    if (lo != hi)
      throw InputError(fmt::format("boundary: periodic must be set on both {} sides",
                                   axis == 0 ? "x" : "y"));
  }
}

BoundaryKind boundary_kind(const std::string& name) {
  if (name == "periodic") return BoundaryKind::periodic;
  if (name == "outflow") return BoundaryKind::outflow;
  if (name == "inflow") return BoundaryKind::inflow;
  if (name == "reflecting") return BoundaryKind::reflecting;
  if (name == "wall") return BoundaryKind::wall;
  throw InputError(fmt::format(
      "unknown boundary '{}' (expected periodic, outflow, inflow, reflecting or wall)", name));
}

GhostFiller::GhostFiller(const VelocityModel& model, const MomentInversion& inversion, double b,
                         const Lattice& lattice, const Boundaries& boundaries)
    : model_(model), inversion_(inversion), b_(b), lattice_(lattice), boundaries_(boundaries) {
  boundaries_.check();
  for (int axis = 0; axis < 2; ++axis) {
    const auto kind_lo = boundaries_.side[2 * axis].kind;
    const auto kind_hi = boundaries_.side[2 * axis + 1].kind;
    if (kind_lo == BoundaryKind::reflecting || kind_hi == BoundaryKind::reflecting)
      mirror_[axis] = model.mirror(axis);
  }
}

Macro GhostFiller::moments_at(const std::vector<double>& f, std::size_t cell) const {
  return macro_of(model_, f.data() + cell, lattice_.cells(), b_);
}

void GhostFiller::fill(std::vector<double>& f) const {
  for (int side = 0; side < 4; ++side) fill_side(f, side);
}

void GhostFiller::fill_side(std::vector<double>& f, int side) const {
  const int axis = side / 2;
  const bool high = side % 2 == 1;
  const int n = axis == 0 ? lattice_.nx : lattice_.ny;
  // x sides fill interior rows; y sides fill every column including the x ghosts (corners).
  const int g = Lattice::ghosts;
  const int along_lo = axis == 0 ? 0 : -g;
  const int along_hi = axis == 0 ? lattice_.ny : lattice_.nx + g;
  const std::size_t N = lattice_.cells();
  const int Q = model_.size();
  const BoundarySide& bc = boundaries_.side[side];
  std::vector<double> ghost_eq(Q), fluid_eq(Q);
  for (int a = along_lo; a < along_hi; ++a) {
    for (int m = 0; m < g; ++m) {
      // Ghost layer m (0 = next to the boundary) and its source cells.
      const int ghost = high ? n + m : -1 - m;
      const int mirror = std::clamp(high ? n - 1 - m : m, 0, n - 1);
      const int periodic = ((ghost % n) + n) % n;
      const int nearest = high ? n - 1 : 0;
      auto cell = [&](int c) { return axis == 0 ? lattice_.at(c, a) : lattice_.at(a, c); };
      const std::size_t dst = cell(ghost);
      switch (bc.kind) {
        case BoundaryKind::periodic:
          for (int k = 0; k < Q; ++k) f[k * N + dst] = f[k * N + cell(periodic)];
          break;
        case BoundaryKind::outflow:
          for (int k = 0; k < Q; ++k) f[k * N + dst] = f[k * N + cell(nearest)];
          break;
        case BoundaryKind::inflow:
          inversion_.equilibrium(bc.state.rho, bc.state.ux, bc.state.uy, bc.state.T, b_,
                                 ghost_eq.data());
          for (int k = 0; k < Q; ++k) f[k * N + dst] = ghost_eq[k];
          break;
        case BoundaryKind::reflecting:
          for (int k = 0; k < Q; ++k) f[k * N + dst] = f[mirror_[axis][k] * N + cell(mirror)];
          break;
        case BoundaryKind::wall: {
          const std::size_t src = cell(mirror);
          const Macro fl = moments_at(f, src);
          inversion_.equilibrium(fl.rho, fl.ux, fl.uy, fl.T, b_, fluid_eq.data());
          inversion_.equilibrium(fl.rho, 2 * bc.state.ux - fl.ux, 2 * bc.state.uy - fl.uy,
                                 2 * bc.state.T - fl.T, b_, ghost_eq.data());
          for (int k = 0; k < Q; ++k) f[k * N + dst] = ghost_eq[k] + f[k * N + src] - fluid_eq[k];
          break;
        }
      }
    }
  }
}

}  // namespace shockfield::dbm
