#include "shockfield/mpm/case_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {
namespace {

constexpr const char* kAxes = "xyz";

void check_inside(const Config& t, const GridSpec& g, const Vec3& lo, const Vec3& hi, const char* what) {
  for (int a = 0; a < g.dim; ++a) {
    const double tol = 1e-9 * g.cell_size[a];
    if (lo[a] < g.origin[a] - tol || hi[a] > g.origin[a] + g.length(a) + tol || !(hi[a] > lo[a]))
      t.fail(hi[a] > g.origin[a] + g.length(a) + tol ? "hi" : "lo",
             fmt::format("{} spans [{}, {}] m along {}, outside the grid [{}, {}] m (or empty)", what, lo[a], hi[a],
                         kAxes[a], g.origin[a], g.origin[a] + g.length(a)));
  }
}

// The lateral axes along which the body fills the periodic grid from side to side.
PeriodicAxes filled_periodic_axes(const GridSpec& g, const Body& body, int axis) {
  PeriodicAxes out{false, false, false};
  for (int a = 0; a < g.dim; ++a) {
    const double tol = 1e-9 * g.cell_size[a];
    out[static_cast<std::size_t>(a)] = a != axis && g.periodic[static_cast<std::size_t>(a)] &&
                                       std::abs(body.lo[a] - g.origin[a]) <= tol &&
                                       std::abs(body.hi[a] - g.origin[a] - g.length(a)) <= tol;
  }
  return out;
}

Void mirrored(const Void& v, int axis, double plane) {
  Void m = v;
  m.centre[axis] = 2.0 * plane - v.centre[axis];
  return m;
}

}  // namespace

BuiltSample build_sample(const MpmCase& c, const Config& root) {
  BuiltSample out;
  const auto tables = root.tables("body");
  const int dim = c.grid.dim, axis = c.axis();
  double plane = c.grid.origin[axis];  // impact plane of a symmetric impact: the top of the bodies
  for (const BodySpec& b : c.bodies) plane = std::max(plane, b.body.hi[axis]);

  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const Config& t = tables[k];
    Body body = c.bodies[k].body;
    body.id = static_cast<int>(k);  // contact body k; a symmetric impact's mirror image is body count + k
    check_inside(t, c.grid, body.lo, body.hi, "the body");
    if (c.options.shape != ShapeKind::Linear && !(body.spacing < c.grid.cell_size[0]))
      t.fail("spacing", fmt::format("{} m: GIMP needs a particle spacing below the cell size {} m", body.spacing,
                                    c.grid.cell_size[0]));
    if ((c.loading == LoadingKind::Wall || c.loading == LoadingKind::Tensile) &&
        body.lo[axis] - c.grid.origin[axis] > c.grid.cell_size[axis])
      t.fail("lo", fmt::format("the body starts at {} m along {}; a wall {} loading needs it within one cell of the "
                               "wall at {} m", body.lo[axis], kAxes[axis],
                               c.loading == LoadingKind::Wall ? "impact" : "(tensile)", c.grid.origin[axis]));
    std::vector<Void> voids;
    try {
      if (c.bodies[k].pores)
        voids = place_voids(dim, body, *c.bodies[k].pores, filled_periodic_axes(c.grid, body, axis));
    } catch (const InputError& e) {
      t.fail("porosity", e.what());
    }
    if (const auto& cav = c.bodies[k].cavity) {
      try {
        voids.push_back(cavity_at(dim, body, cav->depth, cav->radius));
      } catch (const InputError& e) {
        t.fail("cavity_depth", e.what());
      }
      if (!out.cavity) out.cavity = voids.back(), out.cavity_spacing = body.spacing;
    }
    BodyStats stats = add_body(out.particles, dim, body, c.materials[static_cast<std::size_t>(body.material)], voids);
    if (c.loading == LoadingKind::Symmetric) {
      Body partner = body;
      partner.lo[axis] = 2.0 * plane - body.hi[axis];
      partner.hi[axis] = 2.0 * plane - body.lo[axis];
      partner.velocity = -body.velocity;
      partner.id = static_cast<int>(c.bodies.size() + k);
      check_inside(t, c.grid, partner.lo, partner.hi, "the mirrored partner of the body (symmetric impact)");
      std::vector<Void> images;
      for (const Void& v : voids) images.push_back(mirrored(v, axis, plane));
      const BodyStats s2 = add_body(out.particles, dim, partner, c.materials[static_cast<std::size_t>(body.material)], images);
      stats.lattice_points += s2.lattice_points;
      stats.added += s2.added;
    }
    if (stats.added == 0) t.fail("lo", "the body has no particles (every lattice point lies in a void)");
    out.stats.push_back(stats);
  }
  return out;
}

}  // namespace shockfield::mpm
