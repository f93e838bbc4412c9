#include "shockfield/dbm/boundary.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

const std::vector<std::string>& boundary_kind_names() {
  static const std::vector<std::string> names{"periodic",        "outflow",    "inflow",
                                              "subsonic_inflow", "reflecting", "wall"};
  return names;
}

BoundaryKind boundary_kind(const std::string& name) {
  const auto& names = boundary_kind_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw InputError(fmt::format("unknown boundary '{}' (expected {})", name, fmt::join(names, ", ")));
  return static_cast<BoundaryKind>(it - names.begin());
}

namespace {
// Velocity into the domain through a side (the normal velocity of a low side, minus it on a high side).
double inward(const Macro& m, int axis, bool high) { return (high ? -1.0 : 1.0) * (axis == 0 ? m.ux : m.uy); }
}  // namespace

Macro subsonic_inflow_state(const Macro& imposed, const Macro& interior, int axis, bool high,
                            double gamma) {
  // Riemann invariants J± = u_n ± 2c/(γ−1) of the 1D Euler equations (Toro, Riemann Solvers and
  // Numerical Methods for Fluid Dynamics, 3rd ed., §3.1.3) with c² = γT (p = ρT); entropy
  // s = p/ρ^γ = T/ρ^(γ−1). Incoming: J⁺ and s (and the tangential velocity); outgoing: J⁻.
  const double k = 2.0 / (gamma - 1.0);
  const double j_in = inward(imposed, axis, high) + k * std::sqrt(gamma * imposed.T);
  const double j_out = inward(interior, axis, high) - k * std::sqrt(gamma * interior.T);
  const double un = 0.5 * (j_in + j_out), c = (j_in - j_out) / (2.0 * k);
  if (!(c > 0.0))
    throw RunError(fmt::format(
        "subsonic_inflow: the fluid next to the side leaves faster than the imposed state can follow "
        "(outgoing invariant {:.4g} >= incoming {:.4g}): no positive sound speed at the side",
        j_out, j_in));
  const double T = c * c / gamma;
  const double entropy = imposed.T / std::pow(imposed.rho, gamma - 1.0);
  Macro m = imposed;
  m.rho = std::pow(T / entropy, 1.0 / (gamma - 1.0));
  m.T = T;
  (axis == 0 ? m.ux : m.uy) = (high ? -1.0 : 1.0) * un;
  return m;
}

void check_subsonic_inflow(const Macro& state, int axis, bool high, double gamma) {
  const double un = inward(state, axis, high), c = std::sqrt(gamma * state.T);
  if (!(un > 0.0 && un < c))
    throw InputError(fmt::format(
        "subsonic_inflow needs gas entering slower than sound: velocity into the domain {:.4g} "
        "is not in (0, c = {:.4g}); use inflow for a supersonic stream, outflow for one leaving",
        un, c));
}

GhostFiller::GhostFiller(const VelocityModel& model, const MomentInversion& inversion, double b,
                         const Lattice& lattice, const Boundaries& boundaries)
    : model_(model),
      inversion_(inversion),
      b_(b),
      gamma_((b + 2.0) / b),
      lattice_(lattice),
      boundaries_(boundaries) {
  boundaries_.check();
  for (int axis = 0; axis < 2; ++axis) {
    const auto kind_lo = boundaries_.side[2 * axis].kind;
    const auto kind_hi = boundaries_.side[2 * axis + 1].kind;
    if (kind_lo == BoundaryKind::reflecting || kind_hi == BoundaryKind::reflecting)
      mirror_[axis] = model.mirror(axis);
  }
  for (int side = 0; side < 4; ++side)
    if (boundaries_.side[side].kind == BoundaryKind::subsonic_inflow)
      check_subsonic_inflow(boundaries_.side[side].state, side / 2, side % 2 == 1, gamma_);
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
        case BoundaryKind::subsonic_inflow: {
          const Macro m = subsonic_inflow_state(bc.state, moments_at(f, cell(nearest)), axis, high, gamma_);
          inversion_.equilibrium(m.rho, m.ux, m.uy, m.T, b_, ghost_eq.data());
          for (int k = 0; k < Q; ++k) f[k * N + dst] = ghost_eq[k];
          break;
        }
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
