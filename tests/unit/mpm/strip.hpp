#pragma once
// Coarse 1D-like MPM strips for wave tests: a 2D plane-strain grid two cells wide, periodic along
// x, so the motion along y is in uniaxial strain. Two bodies meet at y = 0 (contact bodies 0 below,
// 1 above: with options.contact on they can separate). With dim = 3 the same strip is 2 × 2 cells
// wide, periodic along x and y, and the motion is along z (the shock axis is always the last).
#include <algorithm>
#include <map>
#include <vector>

#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace strip {

using shockfield::Vec3;
namespace mpm = shockfield::mpm;

struct Setup {
  double h = 1e-3;         // cell size [m]
  int cells = 200;         // cells per body along y
  int cells_upper = 0;     // cells of the upper body, if not `cells`
  double v_lower = 0.0;    // velocity of the body below y = 0 [m/s]
  double v_upper = 0.0;    // velocity of the body above y = 0 [m/s]
  int dim = 2;             // 2: shock along y; 3: along z
  mpm::SimulationOptions options{};
  int axis() const { return dim - 1; }
};

/// The unit vector of `axis` times `length`.
inline Vec3 along(int axis, double length) {
  Vec3 v = Vec3::Zero();
  v[axis] = length;
  return v;
}

inline mpm::Simulation make(const Setup& s, const shockfield::materials::SolidMaterial& mat) {
  const double len = s.cells * s.h, len_upper = (s.cells_upper > 0 ? s.cells_upper : s.cells) * s.h;
  const int axis = s.axis();
  Vec3 lateral = Vec3::Zero();  // the strip's width, two cells along every axis but the shock's
  for (int a = 0; a < axis; ++a) lateral[a] = 2 * s.h;
  mpm::Particles p;
  mpm::Body lower{along(axis, -len), lateral, s.h / 2, along(axis, s.v_lower), 0};
  mpm::Body upper{Vec3::Zero(), lateral + along(axis, len_upper), s.h / 2, along(axis, s.v_upper), 0, 1};  // contact body 1
  mpm::add_body(p, s.dim, lower, mat);
  mpm::add_body(p, s.dim, upper, mat);
  const double margin = 20 * s.h;
  const auto grid = mpm::impact_grid(s.dim, along(axis, -len - margin), lateral + along(axis, len_upper + margin), s.h);
  return mpm::Simulation(grid, {mat}, std::move(p), s.options);
}

/// Rows of particles (same y up to 1e-3 h) averaged: y, v_y, σ_yy, ρ, T, W_p, the deviator s_yy,
/// the von Mises stress and the equivalent plastic strain ε̄p. `axis` is the strip's shock axis
/// (Setup::axis(): 1 in 2D, 2 in 3D); y, v_y, σ_yy and s_yy are its components.
struct Row {
  double y = 0, vy = 0, syy = 0, rho = 0, t = 0, wp = 0, dev = 0, vm = 0, eqp = 0;
};
inline std::vector<Row> profile(const mpm::Particles& p, double h, int axis = 1) {
  std::map<long, std::pair<Row, int>> rows;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Points keep their lattice row in a strip (no lateral motion): bin by the initial row.
    auto& [r, n] = rows[std::lround(p.x[i][axis] / (0.25 * h))];
    r.y += p.x[i][axis];
    r.vy += p.v[i][axis];
    r.syy += p.state[i].stress()(axis, axis);
    r.rho += p.density(i);
    r.t += p.state[i].temperature;
    r.wp += p.state[i].plastic_work;
    r.dev += p.state[i].deviatoric.s(axis, axis);
    r.vm += shockfield::materials::von_mises(p.state[i].deviatoric.s);
    r.eqp += p.state[i].deviatoric.plastic_strain;
    ++n;
  }
  std::vector<Row> out;
  for (auto& [key, rn] : rows) {
    auto [r, n] = rn;
    out.push_back({r.y / n, r.vy / n, r.syy / n, r.rho / n, r.t / n, r.wp / n, r.dev / n, r.vm / n, r.eqp / n});
  }
  return out;
}

/// Highest y where v_y, scanned from the top down, first reaches `level` (linear interpolation).
inline double front_from_top(const std::vector<Row>& rows, double level) {
  for (std::size_t i = rows.size() - 1; i > 0; --i) {
    const Row &a = rows[i - 1], &b = rows[i];
    if (a.vy >= level && b.vy < level) return b.y + (level - b.vy) / (a.vy - b.vy) * (a.y - b.y);
  }
  return 0.0;
}

/// Mean of a row field over y in [y0, y1].
template <class F>
double mean(const std::vector<Row>& rows, double y0, double y1, F field) {
  double s = 0;
  int n = 0;
  for (const Row& r : rows)
    if (r.y >= y0 && r.y <= y1) {
      s += field(r);
      ++n;
    }
  return n ? s / n : 0.0;
}

}  // namespace strip
