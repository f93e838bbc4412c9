#include "shockfield/md/elastic_constants.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::bar_to_GPa;
using units::metal::nktv2p;

namespace {

using Axes = std::array<std::array<int, 3>, 3>;
constexpr Axes kCubicAxes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr Axes kRotatedAxes{{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};

Simulation make_crystal(const CubicCrystal& crystal, double a0, const Axes& orient,
                        const PotentialFactory& potential, const ElasticSettings& s) {
  LatticeSpec spec = crystal.lattice;
  spec.a0 = a0;
  spec.orient = orient;
  const Lattice lattice(spec);
  const geometry::Box box = lattice.box(s.repeat, {geometry::Boundary::periodic, geometry::Boundary::periodic,
                                                   geometry::Boundary::periodic});
  Atoms atoms;
  atoms.mass = crystal.mass;
  atoms.type_names = crystal.type_names;
  lattice.create_atoms(box, atoms);
  auto pot = potential();
  pot->check_types(atoms);
  const double skin = 1.0;
  return Simulation(box, std::move(atoms), std::move(pot), s.fire_timestep, skin);
}

MinimizeResult relax(Simulation& sim, const ElasticSettings& s, bool box, const std::string& what) {
  MinimizeSettings m;
  m.force_tolerance = s.force_tolerance;
  m.pressure_tolerance = s.pressure_tolerance;
  m.max_iterations = s.max_iterations;
  if (box) m.relax_box = {true, true, true};
  MinimizeResult r = minimize_fire(sim, m);
  if (!r.converged)
    throw RunError(fmt::format("elastic constants: relaxation of {} did not converge ({} after {} iterations, "
                               "max |f| = {:.3g} eV/A, P = {:.3g} {:.3g} {:.3g} bar)",
                               what, r.reason, r.iterations, r.max_force, r.pressure.x(), r.pressure.y(),
                               r.pressure.z()));
  return r;
}

// Virial stress σ = −P (bar) of the crystal at a0 stretched along x by 1 + ε, atoms relaxed.
Voigt6 stress_at_strain(const CubicCrystal& crystal, double a0, const Axes& orient, const PotentialFactory& potential,
                        double strain, const ElasticSettings& s) {
  Simulation sim = make_crystal(crystal, a0, orient, potential, s);
  const double scale = 1.0 + strain;
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i)
    sim.atoms.x[i].x() = sim.box.lo.x() + (sim.atoms.x[i].x() - sim.box.lo.x()) * scale;
  sim.box.hi.x() = sim.box.lo.x() + sim.box.length().x() * scale;
  relax(sim, s, false, fmt::format("the crystal at strain {:g}", strain));
  return -sim.forces.virial / sim.box.volume() * nktv2p;
}

// Central difference ∂σ/∂ε (GPa) of the stretched crystal.
Voigt6 stress_derivative(const CubicCrystal& crystal, double a0, const Axes& orient, const PotentialFactory& potential,
                         const ElasticSettings& s) {
  const Voigt6 plus = stress_at_strain(crystal, a0, orient, potential, s.strain, s);
  const Voigt6 minus = stress_at_strain(crystal, a0, orient, potential, -s.strain, s);
  return (plus - minus) / (2.0 * s.strain) * bar_to_GPa;
}

}  // namespace

CubicElasticConstants cubic_elastic_constants(const CubicCrystal& crystal, const PotentialFactory& potential,
                                              const ElasticSettings& s) {
  if (crystal.lattice.style == LatticeStyle::hcp)
    throw InputError("elastic constants: the hcp lattice is not cubic (give sc, bcc, fcc or diamond)");
  CubicElasticConstants c;
  {
    Simulation sim = make_crystal(crystal, crystal.lattice.a0, kCubicAxes, potential, s);
    c.relaxation = relax(sim, s, true, "the box to zero pressure");
    const Vec3 l = sim.box.length();
    c.a0 = l.sum() / (s.repeat[0] + s.repeat[1] + s.repeat[2]);
    c.cohesive_energy = c.relaxation.energy / static_cast<double>(sim.atoms.nlocal);
  }
  const Voigt6 cubic = stress_derivative(crystal, c.a0, kCubicAxes, potential, s);
  c.c11 = cubic[0];
  c.c12 = 0.5 * (cubic[1] + cubic[2]);
  const Voigt6 rotated = stress_derivative(crystal, c.a0, kRotatedAxes, potential, s);
  c.c44 = 0.5 * (rotated[0] - rotated[1]);
  return c;
}

}  // namespace shockfield::md
