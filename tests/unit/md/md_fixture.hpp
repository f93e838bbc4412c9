#pragma once
// Small MD systems for the tests: an fcc crystal (optionally thermally perturbed) with a
// potential built through the same registry the case files use.
#include <memory>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/md/lattice.hpp"
#include "shockfield/md/potentials/registry.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md::fixture {

inline Atoms fcc_atoms(double a0, std::array<int, 3> n, geometry::Box& box, double mass,
                       std::array<geometry::Boundary, 3> boundary = {geometry::Boundary::periodic,
                                                                     geometry::Boundary::periodic,
                                                                     geometry::Boundary::periodic}) {
  LatticeSpec spec;
  spec.a0 = a0;
  const Lattice lattice(spec);
  box = lattice.box(n, boundary);
  Atoms atoms;
  atoms.mass = {mass};
  atoms.type_names = {"Cu"};
  lattice.create_atoms(box, atoms);
  return atoms;
}

/// Moves every atom by a uniform random displacement in [−amplitude, amplitude]³.
inline void perturb(Atoms& atoms, double amplitude, std::uint64_t seed) {
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    for (int d = 0; d < 3; ++d)
      atoms.x[i][d] += amplitude * (2.0 * rng::uniform(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(d)) - 1.0);
}

inline std::unique_ptr<Potential> potential_from(const std::string& toml, int ntypes = 1) {
  const Config c = Config::parse(toml, "test.toml");
  return potentials::make_potential(c, ".", ntypes);
}

inline std::unique_ptr<Potential> cu_eam() { return potential_from("style = \"eam\"\nfile = \"Cu_u3.eam\"\n"); }

/// Argon-like LJ in metal units (ε = 0.0104 eV, σ = 3.4 Å, cut 8.5 Å).
inline std::unique_ptr<Potential> argon_lj() {
  return potential_from("style = \"lj/cut\"\nepsilon = 0.0104\nsigma = 3.4\ncutoff = 8.5\n");
}

}  // namespace shockfield::md::fixture
